#include "render/private_display.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <X11/Xlib.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <sstream>

#include "core/util/error.h"

namespace mq::render {
namespace {

// One connection held open for the life of the process: an X server without
// -noreset (xvfb-run's) resets whenever its last client leaves, and a window
// opened during that reset fails ("bad X server connection").
Display* heldDisplay = nullptr;
std::string heldName;
pid_t heldBy = 0;

bool displayAnswers(const char* name) {
  if (heldDisplay && heldBy != getpid()) heldDisplay = nullptr;  // a forked child: the parent's socket, leave it
  if (!name || !*name) return false;
  if (heldDisplay && heldName == name) return true;
  Display* display = XOpenDisplay(name);
  if (!display) return false;
  if (heldDisplay) XCloseDisplay(heldDisplay);
  heldBy = getpid();
  heldDisplay = display;
  heldName = name;
  return true;
}

std::string findInPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / program;
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return {};
}

// Reads the display number Xvfb writes to `fd` once it accepts connections.
std::string readDisplayNumber(int fd, int timeoutMs) {
  std::string number;
  pollfd p{fd, POLLIN, 0};
  while (poll(&p, 1, timeoutMs) > 0) {
    char buffer[16];
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n <= 0) break;
    number.append(buffer, static_cast<size_t>(n));
    if (number.find('\n') != std::string::npos) break;
  }
  while (!number.empty() && (number.back() == '\n' || number.back() == ' ')) number.pop_back();
  return number;
}

class PrivateXvfb {
 public:
  explicit PrivateXvfb(const std::string& xvfb) {
    int fds[2];
    if (pipe(fds) != 0) throw Error("cannot start Xvfb: pipe failed");
    pid_ = fork();
    if (pid_ < 0) throw Error("cannot start Xvfb: fork failed");
    if (pid_ == 0) runXvfb(xvfb, fds[0], fds[1]);
    close(fds[1]);
    const std::string number = readDisplayNumber(fds[0], 15000);
    close(fds[0]);
    if (number.empty()) {
      stop();
      throw Error("Xvfb (" + xvfb + ") did not start; run the command under xvfb-run -a instead");
    }
    display_ = ":" + number;
  }
  ~PrivateXvfb() { stop(); }
  const std::string& display() const { return display_; }
  // A forked child inherits this object but not the server: only the
  // process that started Xvfb may stop it.
  bool ownedByThisProcess() const { return owner_ == getpid(); }

 private:
  [[noreturn]] static void runXvfb(const std::string& xvfb, int readEnd, int writeEnd) {
    close(readEnd);
    prctl(PR_SET_PDEATHSIG, SIGTERM);  // never outlive the process that needs it
    const int devNull = open("/dev/null", O_RDWR);
    if (devNull >= 0) {
      dup2(devNull, STDIN_FILENO);
      dup2(devNull, STDOUT_FILENO);
      dup2(devNull, STDERR_FILENO);
    }
    const std::string fd = std::to_string(writeEnd);
    execl(xvfb.c_str(), "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1920x1080x24", "-nolisten", "tcp",
          "-noreset", static_cast<char*>(nullptr));
    _exit(127);
  }

  void stop() {
    if (pid_ <= 0 || !ownedByThisProcess()) return;
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

  pid_t pid_ = -1;
  pid_t owner_ = getpid();
  std::string display_;
};

std::mutex displayMutex;
std::unique_ptr<PrivateXvfb> privateServer;  // lives until the process exits

}  // namespace

std::string ensureDisplay() {
  std::lock_guard lock(displayMutex);
  const char* current = std::getenv("DISPLAY");
  if (privateServer && !privateServer->ownedByThisProcess()) (void)privateServer.release();  // the parent's
  if (displayAnswers(current)) return current;
  if (privateServer) {  // DISPLAY was changed since: point it back at ours
    setenv("DISPLAY", privateServer->display().c_str(), 1);
    return privateServer->display();
  }
  const std::string xvfb = findInPath("Xvfb");
  if (xvfb.empty())
    throw Error(std::string(current && *current ? "the X display " + std::string(current) + " does not answer"
                                                : "no X display (DISPLAY is not set)") +
                " and Xvfb is not installed: install the xvfb package or run under xvfb-run -a");
  privateServer = std::make_unique<PrivateXvfb>(xvfb);
  setenv("DISPLAY", privateServer->display().c_str(), 1);
  if (!displayAnswers(privateServer->display().c_str()))
    throw Error("the private Xvfb on " + privateServer->display() + " does not answer");
  return privateServer->display();
}

bool usingPrivateDisplay() {
  std::lock_guard lock(displayMutex);
  return privateServer != nullptr;
}

}  // namespace mq::render
