#include "dist/mpi_session.hpp"

#include <cstdlib>

#ifdef RTS_HAVE_MPI
#include <mpi.h>
#endif

namespace rts::dist {

bool launched_by_mpi_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

MpiSession::MpiSession(int* argc, char*** argv) {
#ifdef RTS_HAVE_MPI
  if (!launched_by_mpi_launcher()) return;
  int provided = 0;
  // Only the main thread calls MPI: the root's rendering thread and TBB's workers never do.
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  active_ = true;
#else
  (void)argc;
  (void)argv;
#endif
}

MpiSession::~MpiSession() {
#ifdef RTS_HAVE_MPI
  if (active_) MPI_Finalize();
#endif
}

int MpiSession::agree(int code) const {
#ifdef RTS_HAVE_MPI
  if (!active_) return code;
  int out = code;
  MPI_Allreduce(&code, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return out;
#else
  return code;
#endif
}

int MpiSession::from_root(int value) const {
#ifdef RTS_HAVE_MPI
  if (active_) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
#endif
  return value;
}

void MpiSession::abort(int code) const {
#ifdef RTS_HAVE_MPI
  if (active_) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

}  // namespace rts::dist
