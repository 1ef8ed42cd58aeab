#include "progress_line.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace swept::cli {

namespace {
using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }
}  // namespace

std::string progress_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  char buf[32];
  const long s = std::lround(seconds);
  if (s < 60) std::snprintf(buf, sizeof buf, "%ld s", s);
  else if (s < 3600) std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return buf;
}

ProgressLine::ProgressLine(bool wanted) : on_(wanted && ::isatty(::fileno(stderr))) {}

void ProgressLine::restart_locked(const std::string& phase) {
  if (phase == phase_) return;
  phase_ = phase;
  phase_start_ = Clock::now();
  last_draw_ = {};
}

void ProgressLine::draw_locked(const std::string& line, bool force) {
  const auto now = Clock::now();
  if (!force && last_draw_ != Clock::time_point{} && seconds_between(last_draw_, now) < 0.1) return;
  last_draw_ = now;
  maybe_drawn_ = true;
  last_line_ = line;
  // Carriage return, the line, then erase what a longer earlier line left to its right.
  std::fprintf(stderr, "\r%s\033[K", line.c_str());
  std::fflush(stderr);
}

void ProgressLine::count(const std::string& phase, std::size_t done, std::size_t total, const std::string& unit,
                         const std::string& detail) {
  if (!on_) return;
  const std::lock_guard lock(mutex_);
  restart_locked(phase);
  const double elapsed = seconds_between(phase_start_, Clock::now());
  std::string line = "  " + phase + "  " + std::to_string(done) + "/" + std::to_string(total) + (unit.empty() ? "" : " " + unit);
  if (done > 0 && elapsed > 0.05) {
    const double rate = static_cast<double>(done) / elapsed;
    char buf[64];
    std::snprintf(buf, sizeof buf, rate >= 10 ? "  %.0f/s" : "  %.2g/s", rate);
    line += buf;
    if (done < total) line += "  ETA " + progress_duration(static_cast<double>(total - done) / rate);
  }
  if (!detail.empty()) line += "  " + detail;
  draw_locked(line, done >= total);
}

void ProgressLine::fraction(const std::string& phase, double f) {
  if (!on_) return;
  const std::lock_guard lock(mutex_);
  restart_locked(phase);
  f = std::isfinite(f) ? std::min(std::max(f, 0.0), 1.0) : 0.0;
  const double elapsed = seconds_between(phase_start_, Clock::now());
  char buf[64];
  std::snprintf(buf, sizeof buf, "  %3.0f %%", 100.0 * f);
  std::string line = "  " + phase + buf;
  if (f > 0.01 && f < 1.0 && elapsed > 0.5) line += "  ETA " + progress_duration(elapsed * (1.0 - f) / f);
  draw_locked(line, f >= 1.0);
}

void ProgressLine::clear() {
  if (!on_) return;
  const std::lock_guard lock(mutex_);
  if (!maybe_drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  maybe_drawn_ = false;
  phase_.clear();
  last_line_.clear();
}

void ProgressLine::message(const std::string& text) {
  const std::lock_guard lock(mutex_);
  if (!on_ || last_line_.empty()) {
    std::fprintf(stderr, "%s\n", text.c_str());
    return;
  }
  std::fprintf(stderr, "\r\033[K%s\n%s\033[K", text.c_str(), last_line_.c_str());
  std::fflush(stderr);
}

std::function<void(const ImportProgress&)> ProgressLine::import_progress(const std::string& file) {
  if (!on_) return {};
  maybe_drawn_ = true;  // the child process may draw
  return [this, file](const ImportProgress& p) { fraction("reading " + file + "  " + p.phase, p.fraction); };
}

Result<ImportedModel> import_mesh_with_progress(const std::string& file, ImportOptions options, bool quiet) {
  ProgressLine line(!quiet);
  options.progress = line.import_progress(std::filesystem::path(file).filename().string());
  return import_mesh(file, options);
}

}  // namespace swept::cli
