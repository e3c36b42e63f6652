#pragma once

// What an interrupted zrender removes before it dies: the private folders of the outputs being
// written (io/OutputFile.hpp) and the one file each may hold (docs/design.md, Outputs). A
// signal handler can only reach what the whole process sees, so this list is the one
// process-wide mutable state of the project; everything in it is lock-free and async-signal-safe.

#include <atomic>
#include <csignal>
#include <string>

namespace zrender {

// A private folder, and the file in it, as the signal handler removes them. The paths are set
// before the entry is listed and stay unchanged while it is; the flags say what exists on disk.
struct InFlightFiles {
  std::string folder;
  std::string file;
  std::atomic<bool> folderMade{false};
  std::atomic<bool> fileMade{false};
};

inline constexpr int kMaxInFlight = 4096;
// Lists `entry` for the handler; false when the list is full (kMaxInFlight entries at once).
bool listInFlight(InFlightFiles* entry);
// Takes `entry` off the list; after it returns, the handler no longer reads it.
void unlistInFlight(InFlightFiles* entry);

// Wraps the step that makes a listed entry's folder or file and sets its flag. A handler waits
// for every such step under way before it reads the list, and none starts once a handler has
// begun (the thread then waits for the end); the handled signals wait on the calling thread
// meanwhile, so the handler never runs in the middle of the step it would wait for.
class MakingInFlight {
 public:
  MakingInFlight();
  ~MakingInFlight();
  MakingInFlight(const MakingInFlight&) = delete;
  MakingInFlight& operator=(const MakingInFlight&) = delete;

 private:
  sigset_t old_;
};

// Installs the handler for SIGINT, SIGTERM and SIGHUP: it removes every listed file and folder,
// then ends the process by the same signal with its default action (a shell reports 130 for
// SIGINT, 143 for SIGTERM).
void removeInFlightFilesOnSignals();

}  // namespace zrender
