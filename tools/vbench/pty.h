// Pty: a pseudo-terminal whose slave side host tools open like a serial
// port (vbench --pty bridges the virtual Mega's UART1 to it).
#ifndef STRIDER_VBENCH_PTY_H
#define STRIDER_VBENCH_PTY_H

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

namespace strider_vmega {

struct Pty {
  int master = -1;
  int slave = -1;  // kept open so the master never sees a hang-up
  std::string path;
  bool open_pty(std::string* error) {
    master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) {
      *error = std::string("posix_openpt: ") + std::strerror(errno);
      return false;
    }
    const char* name = ptsname(master);
    if (!name) {
      *error = "ptsname failed";
      return false;
    }
    path = name;
    slave = ::open(name, O_RDWR | O_NOCTTY);
    if (slave >= 0) {
      termios t;
      if (tcgetattr(slave, &t) == 0) {
        cfmakeraw(&t);
        tcsetattr(slave, TCSANOW, &t);
      }
    }
    fcntl(master, F_SETFL, fcntl(master, F_GETFL) | O_NONBLOCK);
    return true;
  }
  std::string read_available() {
    std::string out;
    char buf[256];
    for (;;) {
      const ssize_t n = ::read(master, buf, sizeof buf);
      if (n <= 0) break;
      out.append(buf, size_t(n));
    }
    return out;
  }
  void write_bytes(const std::string& s) {
    size_t off = 0;
    while (off < s.size()) {
      const ssize_t n = ::write(master, s.data() + off, s.size() - off);
      if (n <= 0) break;  // nobody reads: drop, as a radio link would
      off += size_t(n);
    }
  }
};

}  // namespace strider_vmega

#endif  // STRIDER_VBENCH_PTY_H
