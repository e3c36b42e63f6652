#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>

namespace zrender {

// How a run of several views shows its progress on stderr (--progress): a bar redrawn in place,
// or a line at most every few seconds (a log, where a bar's carriage returns would be noise).
enum class ProgressMode { None, Bar, Lines };

// --progress auto|bar|lines|none as a mode; `auto` is a bar on a terminal, lines elsewhere,
// and none for a single view. InputError for another word.
ProgressMode progressMode(const std::string& option, bool terminal, size_t views);

// Counts views done and reports them: views done of all, views per second, time left.
class Progress {
 public:
  // `clock`: milliseconds, increasing (nowMs; a test's own).
  Progress(std::ostream& err, ProgressMode mode, size_t total, double intervalMs,
           std::function<double()> clock);
  void viewDone();  // in order, from one thread at a time
  void finish();    // clears the bar

 private:
  std::string status() const;

  std::ostream& err_;
  ProgressMode mode_;
  size_t total_, done_ = 0;
  double intervalMs_, startMs_, lastMs_;
  std::function<double()> clock_;
  bool drawn_ = false;
};

}  // namespace zrender
