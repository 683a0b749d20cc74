#include "lsp/stdio.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

#include "lsp/framing.hpp"

namespace rts::lsp {

namespace {

bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// True when more input is already waiting (then diagnostics wait for it: edits coalesce).
bool input_waiting(int fd) {
  pollfd p{fd, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0 && (p.revents & (POLLIN | POLLHUP));
}

}  // namespace

int run_stdio(ServerOptions options) {
  // An editor that closes the pipe must not kill the server mid-write with SIGPIPE; the write
  // fails instead and the loop ends.
  std::signal(SIGPIPE, SIG_IGN);
  bool output_ok = true;
  Server server(std::move(options), [&](const std::string& body) {
    if (output_ok) output_ok = write_all(STDOUT_FILENO, frame(body));
  });
  MessageReader reader;
  std::string body, error;
  char buf[1 << 16];
  while (!server.exited() && output_ok) {
    ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of input: the editor is gone
    reader.feed(std::string_view(buf, static_cast<std::size_t>(n)));
    for (;;) {
      MessageReader::Status s = reader.next(body, error);
      if (s == MessageReader::Status::NeedMore) break;
      if (s == MessageReader::Status::Error) server.framing_error(error);
      else server.handle(body);
      if (server.exited()) break;
    }
    if (!server.exited() && !input_waiting(STDIN_FILENO)) server.flush();
  }
  return server.exited() ? server.exit_code() : 1;
}

}  // namespace rts::lsp
