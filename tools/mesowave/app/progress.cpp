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

void Progress::update(std::int64_t done, int stop_signal) {
  if (!finished_) done_ = done;
  if (stop_signal != 0) throw Interrupted{stop_signal, mark()};
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

void Progress::finish_early(std::int64_t done, const std::string& why) {
  if (!finished_) done_ = done;
  mark_progress(mark());
  if (!enabled_ || finished_) return;
  draw(done_, true, why);
  finished_ = true;
}

void Progress::draw(std::int64_t done, bool final, const std::string& stopped_because) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = double(done) / double(total_);
  // A rate needs steps done and time passed: the first plain line (at 0 %) comes right after the
  // start, where a few steps over microseconds give a meaningless rate and an ETA of 0:00.
  const bool measured = done > resumed_at_ && elapsed >= 0.05;
  const double rate = measured ? double(done - resumed_at_) / elapsed : 0.0;
  char numbers[256];
  const int head = std::snprintf(numbers, sizeof numbers, "%3d%% %lld/%lld %s", int(100 * fraction), (long long)done,
                                 (long long)total_, unit_.c_str());
  const std::size_t used = std::min(std::size_t(std::max(head, 0)), sizeof numbers - 1);
  if (final && !stopped_because.empty())
    std::snprintf(numbers + used, sizeof numbers - used, ", stopped early: %s; took %s", stopped_because.c_str(),
                  clock_text(elapsed).c_str());
  else if (final)
    std::snprintf(numbers + used, sizeof numbers - used, ", %.3g %s/s, took %s",
                  elapsed > 0 ? double(done - resumed_at_) / elapsed : 0.0, unit_.c_str(), clock_text(elapsed).c_str());
  else if (measured)
    std::snprintf(numbers + used, sizeof numbers - used, ", %.3g %s/s, ETA %s", rate, unit_.c_str(),
                  clock_text(double(total_ - done) / rate).c_str());
  else
    std::snprintf(numbers + used, sizeof numbers - used, ", started");
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
