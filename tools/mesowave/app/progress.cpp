#include "mesowave/app/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace mesowave::app {
namespace {

std::string clock_text(double seconds) {
  const auto s = std::int64_t(seconds + 0.5);
  char text[32];
  if (s >= 3600) std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", (long long)(s / 3600), (long long)(s / 60 % 60), (long long)(s % 60));
  else std::snprintf(text, sizeof text, "%lld:%02lld", (long long)(s / 60), (long long)(s % 60));
  return text;
}

}  // namespace

Progress::Progress(std::string label, std::int64_t total, std::string unit, bool enabled, std::int64_t resumed_at)
    : label_(std::move(label)), unit_(std::move(unit)), total_(std::max<std::int64_t>(total, 1)), done_(resumed_at),
      resumed_at_(resumed_at), enabled_(enabled), tty_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() {
  mark_progress(mark());
  if (!finished_ && enabled_ && tty_) std::fputc('\n', stderr);
}

ProgressMark Progress::mark() const { return {label_, unit_, done_, total_}; }

void Progress::update(std::int64_t done) {
  if (!finished_) done_ = done;
  if (const int signal = interrupt_signal()) throw Interrupted{signal, mark()};
  if (!enabled_ || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  if (tty_) {
    if (now - last_draw_ < std::chrono::milliseconds(200)) return;
    last_draw_ = now;
    draw(done, false);
  } else {
    const int decile = int(10 * done / total_);
    if (decile > last_decile_ && decile < 10) {
      last_decile_ = decile;
      draw(done, false);
    }
  }
}

void Progress::finish() {
  if (!finished_) done_ = total_;
  mark_progress(mark());
  if (!enabled_ || finished_) return;
  draw(total_, true);
  finished_ = true;
}

void Progress::draw(std::int64_t done, bool final) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? double(done - resumed_at_) / elapsed : 0.0;
  const double eta = rate > 0 ? double(total_ - done) / rate : 0.0;
  const double fraction = double(done) / double(total_);
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, "%3d%% %lld/%lld %s, %.3g %s/s, %s %s", int(100 * fraction), (long long)done,
                (long long)total_, unit_.c_str(), rate, unit_.c_str(), final ? "took" : "ETA",
                clock_text(final ? elapsed : eta).c_str());
  if (tty_) {
    const int width = 24, filled = int(width * fraction);
    std::fprintf(stderr, "\r%s [%s%s] %s\033[K%s", label_.c_str(), std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), numbers, final ? "\n" : "");
  } else {
    std::fprintf(stderr, "%s: %s\n", label_.c_str(), numbers);
  }
  std::fflush(stderr);
}

}  // namespace mesowave::app
