#include "plyform/app/stop_signals.hpp"

#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <cstdlib>
#include <thread>

namespace plyform::app {
namespace {

std::atomic<bool> watching{false};
// The run's flag while a run lasts (else null).
std::atomic<volatile std::sig_atomic_t*> armed{nullptr};
volatile std::sig_atomic_t* handled_flag = nullptr;

sigset_t stop_set() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

// The signal's default action, now, on this thread: the process ends as it would have.
[[noreturn]] void end_by(int signal) {
  std::signal(signal, SIG_DFL);
  sigset_t one;
  sigemptyset(&one);
  sigaddset(&one, signal);
  pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
  raise(signal);
  std::_Exit(128 + signal);  // not reached: the default action of both ends the process
}

void watch() {
  const sigset_t set = stop_set();
  while (true) {
    int signal = 0;
    if (sigwait(&set, &signal) != 0)
      continue;
    volatile std::sig_atomic_t* flag = armed.load();
    if (flag == nullptr || *flag != 0)
      end_by(signal);
    *flag = 1;
  }
}

extern "C" void request_stop(int signal) {
  *handled_flag = 1;
  std::signal(signal, SIG_DFL);
}

}  // namespace

void watch_stop_signals() {
  const sigset_t set = stop_set();
  if (pthread_sigmask(SIG_BLOCK, &set, nullptr) != 0)
    return;  // the handlers of StopOnSignals then
  std::thread(watch).detach();
  watching = true;
}

StopOnSignals::StopOnSignals(volatile std::sig_atomic_t* flag) {
  *flag = 0;
  if (watching) {
    armed = flag;
    return;
  }
  handled_flag = flag;
  int_ = std::signal(SIGINT, request_stop);
  term_ = std::signal(SIGTERM, request_stop);
}

StopOnSignals::~StopOnSignals() {
  if (watching) {
    armed = nullptr;
    return;
  }
  std::signal(SIGINT, int_);
  std::signal(SIGTERM, term_);
}

}  // namespace plyform::app
