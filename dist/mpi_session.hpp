// MPI for `mpirun -np N rts render` (docs/scale-out.md). The binary joins MPI only when a
// launcher started it (Open MPI's, or a PMI/PMIx one such as Slurm's srun): run alone it never
// calls MPI_Init and behaves exactly as a build without MPI.
#pragma once

namespace rts::dist {

// True when this process was started by mpirun/srun (their environment variables are set).
bool launched_by_mpi_launcher();

// Initialises MPI on construction when launched by a launcher (and rts was built with MPI),
// finalises on destruction. rank() is 0 and size() 1 otherwise.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  bool active() const { return active_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  // The largest of every rank's `code` (a collective: every rank calls it at the same point),
  // so that all ranks agree whether to go on; `code` itself when MPI is not active.
  int agree(int code) const;
  // Rank 0's `value`, on every rank (a collective).
  int from_root(int value) const;
  // Ends the whole job with `code` (a rank that cannot go on while others wait for it).
  [[noreturn]] void abort(int code) const;

 private:
  bool active_ = false;
  int rank_ = 0, size_ = 1;
};

}  // namespace rts::dist
