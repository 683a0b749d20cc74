#include "dist/mpi_session.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

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
  // This build has no MPI: when a launcher started it, become rts-mpi (the same program with
  // Open MPI, built beside it), so that plain runs never load MPI's libraries.
  (void)argc;
  if (!launched_by_mpi_launcher()) return;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::string mpi_exe = ec ? std::string() : (exe.parent_path() / "rts-mpi").string();
  if (!mpi_exe.empty() && ::access(mpi_exe.c_str(), X_OK) == 0) {
    ::execv(mpi_exe.c_str(), *argv);
  }
  std::cerr << "rts: warning: started by an MPI launcher, but this rts has no MPI (rts-mpi is not beside it): "
               "every rank renders the whole image alone\n";
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
