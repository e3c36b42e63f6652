#include "zrender/io/files/InterruptCleanup.hpp"

#include <pthread.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>

namespace zrender {

namespace {

// The list the handler reads, the steps under way that make what it lists, and whether a
// handler has begun. Lock-free atomics only: a signal may arrive on any thread.
std::atomic<InFlightFiles*> listed[kMaxInFlight];
std::atomic<int> making{0};
std::atomic<bool> cleaning{false};

[[noreturn]] void waitForTheEnd() {
  for (;;) ::pause();
}

sigset_t handledSignals() {
  sigset_t set;
  sigemptyset(&set);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
  return set;
}

void removeListed(int signal) {
  // A second signal on another thread waits for the first one's removals to end the process.
  if (cleaning.exchange(true)) waitForTheEnd();
  // Steps that began before the store above end (and set their flags) before the list is read;
  // later ones see it and do not begin. Each takes one system call.
  const timespec pause{0, 100000};
  while (making.load() > 0) ::nanosleep(&pause, nullptr);
  for (auto& slot : listed) {
    const InFlightFiles* entry = slot.load();
    if (!entry) continue;
    if (entry->fileMade.load()) ::unlink(entry->file.c_str());
    if (entry->folderMade.load()) ::rmdir(entry->folder.c_str());
  }
  // The default action, raised while this handler still blocks the signal: it ends the
  // process as the signal asks as soon as the handler returns.
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  ::sigaction(signal, &fallback, nullptr);
  ::raise(signal);
}

}  // namespace

bool listInFlight(InFlightFiles* entry) {
  for (auto& slot : listed) {
    InFlightFiles* empty = nullptr;
    if (slot.compare_exchange_strong(empty, entry)) return true;
  }
  return false;
}

void unlistInFlight(InFlightFiles* entry) {
  for (auto& slot : listed) {
    InFlightFiles* expected = entry;
    if (slot.compare_exchange_strong(expected, nullptr)) break;
  }
  // A handler may still be reading the entry, which the caller is about to free.
  if (cleaning.load()) waitForTheEnd();
}

MakingInFlight::MakingInFlight() {
  const sigset_t held = handledSignals();
  ::pthread_sigmask(SIG_BLOCK, &held, &old_);
  making.fetch_add(1);
  if (cleaning.load()) {
    making.fetch_sub(1);
    waitForTheEnd();
  }
}

MakingInFlight::~MakingInFlight() {
  making.fetch_sub(1);
  ::pthread_sigmask(SIG_SETMASK, &old_, nullptr);
}

void removeInFlightFilesOnSignals() {
  struct sigaction action {};
  action.sa_handler = removeListed;
  action.sa_mask = handledSignals();
  for (int s : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(s, &action, nullptr);
}

}  // namespace zrender
