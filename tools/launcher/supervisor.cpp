#include "supervisor.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <optional>

namespace swarm::tools {
namespace {

using Clock = std::chrono::steady_clock;

// ---- Signals -> wake-up pipes -----------------------------------------------------------------
// The handler writes the signal number as one byte into the pipe of every supervisor call in
// progress (self-pipe trick), so each call's poll() wakes up. Pipes are created once per slot and
// never closed, so a handler racing with a call's end can never write into a reused descriptor.

constexpr int kSlots = 64;
std::array<std::atomic<int>, kSlots> g_slot_write_fd{};  // 0 = slot has no pipe yet
std::array<std::atomic<bool>, kSlots> g_slot_in_use{};
std::array<int, kSlots> g_slot_read_fd{};

std::mutex g_handlers_mutex;
int g_handler_users = 0;
struct sigaction g_old_int {}, g_old_term {}, g_old_chld {};
bool g_int_installed = false, g_term_installed = false;

extern "C" void supervisor_on_signal(int sig) {
  const int saved_errno = errno;
  const unsigned char byte = static_cast<unsigned char>(sig);
  for (int i = 0; i < kSlots; ++i) {
    const int fd = g_slot_write_fd[i].load(std::memory_order_acquire);
    if (fd > 0 && g_slot_in_use[i].load(std::memory_order_acquire)) {
      [[maybe_unused]] const ssize_t n = ::write(fd, &byte, 1);  // non-blocking; full = enough
    }
  }
  errno = saved_errno;
}

// One call's hold on a slot and on the process's signal handlers.
class SignalWake {
 public:
  SignalWake() {
    std::lock_guard<std::mutex> lock(g_handlers_mutex);
    for (int i = 0; i < kSlots; ++i) {
      if (g_slot_in_use[i].load()) continue;
      if (g_slot_write_fd[i].load() == 0) {
        int fds[2];
        if (::pipe2(fds, O_CLOEXEC | O_NONBLOCK) != 0) return;
        g_slot_read_fd[i] = fds[0];
        g_slot_write_fd[i].store(fds[1], std::memory_order_release);
      }
      slot_ = i;
      drain();  // bytes a signal left while the slot was free
      g_slot_in_use[i].store(true, std::memory_order_release);
      break;
    }
    if (slot_ < 0) return;
    if (g_handler_users++ == 0) install();
  }

  ~SignalWake() {
    if (slot_ < 0) return;
    std::lock_guard<std::mutex> lock(g_handlers_mutex);
    g_slot_in_use[slot_].store(false, std::memory_order_release);
    if (--g_handler_users == 0) uninstall();
  }

  SignalWake(const SignalWake&) = delete;
  SignalWake& operator=(const SignalWake&) = delete;

  bool ok() const { return slot_ >= 0; }
  int fd() const { return g_slot_read_fd[slot_]; }

  // Reads every pending byte; returns whether SIGINT or SIGTERM was among them.
  bool drain() {
    bool stop = false;
    unsigned char buf[64];
    while (true) {
      const ssize_t n = ::read(g_slot_read_fd[slot_], buf, sizeof buf);
      if (n <= 0) break;
      for (ssize_t i = 0; i < n; ++i) stop |= buf[i] == SIGINT || buf[i] == SIGTERM;
    }
    return stop;
  }

 private:
  static void install() {
    struct sigaction sa {};
    sa.sa_handler = supervisor_on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    // A SIGINT the process ignores (started in the background by a non-interactive shell) stays
    // ignored, as a shell user would expect.
    struct sigaction current {};
    ::sigaction(SIGINT, nullptr, &current);
    g_int_installed = current.sa_handler != SIG_IGN;
    if (g_int_installed) ::sigaction(SIGINT, &sa, &g_old_int);
    ::sigaction(SIGTERM, nullptr, &current);
    g_term_installed = current.sa_handler != SIG_IGN;
    if (g_term_installed) ::sigaction(SIGTERM, &sa, &g_old_term);
    sa.sa_flags = SA_RESTART | SA_NOCLDSTOP;
    ::sigaction(SIGCHLD, &sa, &g_old_chld);
  }

  static void uninstall() {
    if (g_int_installed) ::sigaction(SIGINT, &g_old_int, nullptr);
    if (g_term_installed) ::sigaction(SIGTERM, &g_old_term, nullptr);
    ::sigaction(SIGCHLD, &g_old_chld, nullptr);
  }

  int slot_ = -1;
};

// ---- Children -----------------------------------------------------------------------------------

struct Child {
  const ProcessSpec* spec = nullptr;
  pid_t pid = 0;
  int log_fd = -1;
  int out_fd = -1;  // read end of the stdout pipe (echo_stdout only)
  bool running = false;
  std::optional<std::chrono::steady_clock::time_point> restart_at;  // killed on purpose: start again then
  bool restarted = false;
};

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

// Writes all of `n` bytes unless the descriptor fails; returns false on failure.
bool write_all(int fd, const char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w > 0) {
      data += w;
      n -= static_cast<std::size_t>(w);
    } else if (w < 0 && errno == EINTR) {
      continue;
    } else if (w < 0 && errno == EAGAIN) {
      pollfd p{fd, POLLOUT, 0};
      if (::poll(&p, 1, 1000) <= 0) return false;
    } else {
      return false;
    }
  }
  return true;
}

std::string describe_status(const std::string& name, int status) {
  if (WIFEXITED(status)) {
    return "process " + name + " failed (exit code " + std::to_string(WEXITSTATUS(status)) + ")";
  }
  const int sig = WTERMSIG(status);
  const char* what = ::sigdescr_np(sig);  // thread-safe, unlike strsignal
  return "process " + name + " was killed by signal " + std::to_string(sig) + " (" +
         (what ? what : "unknown") + ")";
}

class Supervisor {
 public:
  Supervisor(const std::vector<ProcessSpec>& specs, std::chrono::seconds timeout,
             std::chrono::milliseconds grace)
      : timeout_(timeout), grace_(grace) {
    children_.reserve(specs.size());
    for (const ProcessSpec& s : specs) children_.push_back(Child{&s});
    result_.pids.assign(specs.size(), 0);
  }

  SupervisorResult run() {
    SignalWake wake;
    if (!wake.ok()) {
      result_.message = "cannot supervise processes: no wake-up pipe (too many at once?)";
      return result_;
    }
    // Writing to a closed stdout must not kill us: take SIGPIPE as EPIPE on this thread.
    sigset_t pipe_set;
    sigemptyset(&pipe_set);
    sigaddset(&pipe_set, SIGPIPE);
    ::pthread_sigmask(SIG_BLOCK, &pipe_set, &entry_mask_);
    parent_pid_ = ::getpid();
    devnull_ = ::open("/dev/null", O_RDONLY | O_CLOEXEC);

    const Clock::time_point start = Clock::now();
    for (Child& c : children_) {
      if (wake.drain()) interrupt();
      if (stopping_) break;
      if (!start_child(c)) break;
    }
    result_.pids.clear();
    for (const Child& c : children_) result_.pids.push_back(c.pid);
    loop(wake, start);
    finish();

    close_fd(devnull_);
    timespec zero{0, 0};
    while (::sigtimedwait(&pipe_set, nullptr, &zero) > 0) {
    }
    ::pthread_sigmask(SIG_SETMASK, &entry_mask_, nullptr);

    if (!stopping_) {
      result_.ok = true;
      result_.message = "all processes exited normally";
    }
    return result_;
  }

 private:
  bool start_child(Child& c) {
    const ProcessSpec& spec = *c.spec;
    auto fail_start = [&](const std::string& why) {
      result_.failed_name = spec.name;
      result_.exit_code = -1;
      result_.log_path = spec.log_path;
      result_.message = "cannot start process " + spec.name + ": " + why;
      begin_stop();
      return false;
    };
    const std::vector<std::string>& args = c.restarted && !spec.restart_argv.empty() ? spec.restart_argv : spec.argv;
    if (args.empty() || args[0].empty()) return fail_start("empty command line");
    close_fd(c.log_fd);
    c.log_fd = ::open(spec.log_path.c_str(), O_WRONLY | O_CREAT | (c.restarted ? 0 : O_TRUNC) | O_APPEND | O_CLOEXEC,
                      0644);
    if (c.log_fd < 0) {
      return fail_start("cannot create its log " + spec.log_path + " (" + std::strerror(errno) +
                        ")");
    }
    int out_pipe[2] = {-1, -1};
    if (spec.echo_stdout && ::pipe2(out_pipe, O_CLOEXEC) != 0) {
      return fail_start(std::string("pipe: ") + std::strerror(errno));
    }
    int err_pipe[2];  // exec failure report: errno, or EOF when exec succeeded
    if (::pipe2(err_pipe, O_CLOEXEC) != 0) {
      close_fd(out_pipe[0]);
      close_fd(out_pipe[1]);
      return fail_start(std::string("pipe: ") + std::strerror(errno));
    }
    if (c.restarted) {
      const std::string line = "--- " + spec.name + " started again (a planned restart) ---\n";
      write_all(c.log_fd, line.data(), line.size());
    }
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int stdout_fd = spec.echo_stdout ? out_pipe[1] : c.log_fd;

    const pid_t pid = ::fork();
    if (pid == 0) {
      // Child: async-signal-safe calls only until exec.
      ::setpgid(0, 0);
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent_pid_) ::_exit(127);  // the supervisor is already gone
      struct sigaction dfl {};
      dfl.sa_handler = SIG_DFL;
      sigemptyset(&dfl.sa_mask);
      ::sigaction(SIGPIPE, &dfl, nullptr);
      ::sigprocmask(SIG_SETMASK, &entry_mask_, nullptr);
      if (devnull_ >= 0) ::dup2(devnull_, STDIN_FILENO);
      ::dup2(stdout_fd, STDOUT_FILENO);
      ::dup2(c.log_fd, STDERR_FILENO);
      ::execv(argv[0], argv.data());
      const int err = errno;
      [[maybe_unused]] const ssize_t n = ::write(err_pipe[1], &err, sizeof err);
      ::_exit(127);
    }
    close_fd(err_pipe[1]);
    close_fd(out_pipe[1]);
    if (pid < 0) {
      const int err = errno;
      close_fd(err_pipe[0]);
      close_fd(out_pipe[0]);
      return fail_start(std::string("fork: ") + std::strerror(err));
    }
    ::setpgid(pid, pid);  // also here, so the group exists before we may signal it
    c.pid = pid;
    c.running = true;
    if (spec.echo_stdout) {
      c.out_fd = out_pipe[0];
      ::fcntl(c.out_fd, F_SETFL, ::fcntl(c.out_fd, F_GETFL) | O_NONBLOCK);
    }
    int exec_errno = 0;
    ssize_t got;
    do {
      got = ::read(err_pipe[0], &exec_errno, sizeof exec_errno);
    } while (got < 0 && errno == EINTR);
    close_fd(err_pipe[0]);
    if (got == static_cast<ssize_t>(sizeof exec_errno)) {
      int status = 0;
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      c.running = false;
      return fail_start(args[0] + ": " + std::strerror(exec_errno));
    }
    return true;
  }

  void begin_stop() {
    if (stopping_) return;
    stopping_ = true;
    for (const Child& c : children_) {
      if (c.running && c.spec->ends_run) {
        winding_down_ = true;
        wind_down_until_ = Clock::now() + kWindDown;
        ::kill(-c.pid, SIGTERM);
        return;
      }
    }
    stop_all();
  }

  void stop_all() {
    winding_down_ = false;
    kill_at_ = Clock::now() + grace_;
    signal_running(SIGTERM);
  }

  void interrupt() {
    if (!stopping_) {
      result_.interrupted = true;
      result_.message = "interrupted; stopped every process";
      begin_stop();
    } else if (!killed_) {
      signal_running(SIGKILL);  // a second Ctrl-C: no more grace
      killed_ = true;
    }
  }

  void signal_running(int sig) {
    for (const Child& c : children_) {
      if (c.running) ::kill(-c.pid, sig);
    }
  }

  // A child waiting for its planned restart counts as running.
  bool any_running() const {
    return std::any_of(children_.begin(), children_.end(),
                       [](const Child& c) { return c.running || c.restart_at.has_value(); });
  }

  bool only_services_running() const {
    return std::none_of(children_.begin(), children_.end(), [](const Child& c) {
      return (c.running || c.restart_at.has_value()) && !c.spec->service;
    });
  }

  // Copies what a child wrote to its stdout to ours and to its log. Returns false at EOF.
  bool pump(Child& c) {
    char buf[65536];
    while (true) {
      const ssize_t n = ::read(c.out_fd, buf, sizeof buf);
      if (n > 0) {
        if (echo_ok_) echo_ok_ = write_all(STDOUT_FILENO, buf, static_cast<std::size_t>(n));
        write_all(c.log_fd, buf, static_cast<std::size_t>(n));
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && errno == EAGAIN) return true;
      close_fd(c.out_fd);
      return false;
    }
  }

  void reap() {
    for (Child& c : children_) {
      if (!c.running) continue;
      int status = 0;
      const pid_t r = ::waitpid(c.pid, &status, WNOHANG);
      if (r == 0) continue;
      if (r < 0 && errno == EINTR) continue;
      c.running = false;
      if (r < 0) continue;  // someone else reaped it; nothing to report
      // A process started again is not killed on purpose a second time.
      const bool planned = (c.spec->killed_on_purpose && !c.restarted && WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) ||
                           (c.spec->service && retiring_);
      // A service ends only when told to: ending by itself (even with status 0) is a failure.
      const bool failed = (!(WIFEXITED(status) && WEXITSTATUS(status) == 0) || (c.spec->service && !retiring_)) &&
                          !planned;
      if (planned && c.spec->restart_after && !c.restarted && !stopping_) {
        c.restart_at = Clock::now() + *c.spec->restart_after;
      }
      // The run's ender died instead of ending the run: nobody else will, so stop the rest now.
      if (winding_down_ && c.spec->ends_run && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) stop_all();
      if (failed && !stopping_) {
        result_.failed_name = c.spec->name;
        result_.log_path = c.spec->log_path;
        result_.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        result_.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
        result_.message = describe_status(c.spec->name, status);
        begin_stop();
      }
    }
  }

  void loop(SignalWake& wake, Clock::time_point start) {
    const std::optional<Clock::time_point> deadline =
        timeout_.count() > 0 ? std::optional(start + timeout_) : std::nullopt;
    while (any_running()) {
      const Clock::time_point now = Clock::now();
      if (!stopping_ && deadline && now >= *deadline) {
        result_.timed_out = true;
        std::string names;
        for (const Child& c : children_) {
          if (c.running) names += (names.empty() ? "" : ", ") + c.spec->name;
        }
        result_.message = "timed out after " + std::to_string(timeout_.count()) +
                          " s; still running: " + names;
        begin_stop();
      }
      for (Child& c : children_) {
        if (!c.restart_at) continue;
        if (stopping_) {
          c.restart_at.reset();  // the run is ending: no restart
        } else if (now >= *c.restart_at) {
          c.restart_at.reset();
          c.restarted = true;
          close_fd(c.out_fd);
          start_child(c);
        }
      }
      // The run ended itself (or did not in time): the rest, services included, are stopped.
      if (winding_down_ && (now >= wind_down_until_ || only_services_running())) stop_all();
      if (stopping_ && !winding_down_ && !killed_ && now >= kill_at_) {
        signal_running(SIGKILL);
        killed_ = true;
      }
      if (!stopping_ && !retiring_ && only_services_running()) {
        retiring_ = true;
        retire_kill_at_ = now + grace_;
        signal_running(SIGTERM);
      }
      if (retiring_ && !stopping_ && !killed_ && now >= retire_kill_at_) {
        signal_running(SIGKILL);
        killed_ = true;
      }
      // Sleep until a signal, child output, the next deadline, or 250 ms (a safety net in case
      // a SIGCHLD was taken by someone else's handler).
      auto wait = std::chrono::milliseconds(250);
      auto until = [&](Clock::time_point t) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(t - now) +
                          std::chrono::milliseconds(1);
        wait = std::max(std::chrono::milliseconds(0), std::min(wait, left));
      };
      if (!stopping_ && deadline) until(*deadline);
      for (const Child& c : children_) {
        if (c.restart_at) until(*c.restart_at);
      }
      if (winding_down_) until(wind_down_until_);
      if (stopping_ && !winding_down_ && !killed_) until(kill_at_);
      if (retiring_ && !killed_) until(retire_kill_at_);

      std::vector<pollfd> fds{{wake.fd(), POLLIN, 0}};
      std::vector<Child*> owners{nullptr};
      for (Child& c : children_) {
        if (c.out_fd >= 0) {
          fds.push_back({c.out_fd, POLLIN, 0});
          owners.push_back(&c);
        }
      }
      ::poll(fds.data(), fds.size(), static_cast<int>(wait.count()));
      if (fds[0].revents & POLLIN) {
        if (wake.drain()) interrupt();
      }
      for (std::size_t i = 1; i < fds.size(); ++i) {
        if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) pump(*owners[i]);
      }
      reap();
    }
  }

  void finish() {
    for (Child& c : children_) {
      if (c.out_fd >= 0) pump(c);  // what is left in the pipe (non-blocking)
      close_fd(c.out_fd);
      close_fd(c.log_fd);
      // Whatever a child left in its group (its own children) goes with it.
      if (c.pid > 0) ::kill(-c.pid, SIGKILL);
    }
  }

  std::vector<Child> children_;
  std::chrono::seconds timeout_;
  std::chrono::milliseconds grace_;
  SupervisorResult result_;
  sigset_t entry_mask_{};
  pid_t parent_pid_ = 0;
  int devnull_ = -1;
  bool stopping_ = false;
  bool winding_down_ = false;  // the run's ender was asked to end it; the others are left to finish
  Clock::time_point wind_down_until_{};
  bool killed_ = false;
  bool echo_ok_ = true;
  bool retiring_ = false;  // the work is done; the services are being stopped
  Clock::time_point kill_at_{};
  Clock::time_point retire_kill_at_{};
};

}  // namespace

SupervisorResult run_processes(const std::vector<ProcessSpec>& specs, std::chrono::seconds timeout,
                               std::chrono::milliseconds grace_period) {
  return Supervisor(specs, timeout, grace_period).run();
}

}  // namespace swarm::tools
