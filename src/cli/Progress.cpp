#include "zrender/cli/Progress.hpp"

#include <cmath>
#include <cstdio>
#include <utility>

#include "zrender/base/Error.hpp"

namespace zrender {

namespace {

constexpr int kBarWidth = 30;  // characters

std::string seconds(double s) {
  char text[32];
  if (s < 100.0)
    std::snprintf(text, sizeof text, "%.0f s", s);
  else
    std::snprintf(text, sizeof text, "%.0f min", std::ceil(s / 60.0));
  return text;
}

}  // namespace

ProgressMode progressMode(const std::string& option, bool terminal, size_t views) {
  if (option == "none") return ProgressMode::None;
  if (option == "bar") return ProgressMode::Bar;
  if (option == "lines") return ProgressMode::Lines;
  if (option != "auto")
    throw InputError("command line: --progress: expected auto, bar, lines or none, got '" + option +
                     "'");
  if (views <= 1) return ProgressMode::None;
  return terminal ? ProgressMode::Bar : ProgressMode::Lines;
}

Progress::Progress(std::ostream& err, ProgressMode mode, size_t total, double intervalMs,
                   std::function<double()> clock)
    : err_(err),
      mode_(mode),
      total_(total),
      intervalMs_(intervalMs),
      startMs_(clock()),
      lastMs_(startMs_),
      clock_(std::move(clock)) {}

std::string Progress::status() const {
  const double elapsed = (clock_() - startMs_) / 1000.0;
  char text[96];
  std::snprintf(text, sizeof text, "%zu/%zu views", done_, total_);
  std::string s = text;
  if (elapsed > 0.0 && done_ > 0) {
    const double rate = double(done_) / elapsed;
    std::snprintf(text, sizeof text, ", %.1f views/s, ", rate);
    s += text + seconds(double(total_ - done_) / rate) + " left";
  }
  return s;
}

void Progress::viewDone() {
  ++done_;
  if (mode_ == ProgressMode::None) return;
  const double now = clock_();
  if (mode_ == ProgressMode::Bar) {
    const int filled = total_ ? int(double(kBarWidth) * double(done_) / double(total_)) : 0;
    err_ << "\rzrender: [" << std::string(size_t(filled), '#')
         << std::string(size_t(kBarWidth - filled), '.') << "] " << status() << "  " << std::flush;
    drawn_ = true;
  } else if (now - lastMs_ >= intervalMs_ && done_ < total_) {
    err_ << "zrender: " << status() << "\n" << std::flush;
    lastMs_ = now;
  }
}

void Progress::finish() {
  if (drawn_) err_ << "\r" << std::string(100, ' ') << "\r" << std::flush;
  drawn_ = false;
}

}  // namespace zrender
