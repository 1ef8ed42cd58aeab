#pragma once
/// The one line on stderr that long work redraws: what it is doing, how far, how fast, and when it
/// should be done. Drawn only on a terminal and when the user did not ask for quiet (-q), so that
/// a redirected stderr, a pipe or a log never holds it.
#include "swept/io/mesh_io.h"

#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>

namespace swept::cli {

class ProgressLine {
 public:
  /// On when `wanted` and stderr is a terminal.
  explicit ProgressLine(bool wanted);
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool on() const { return on_; }
  /// "  <phase>  <done>/<total> <unit>  <rate>/s  ETA <t>  <detail>": the rate and the ETA over the phase so
  /// far (a new phase name restarts them). Redrawn at most ten times a second, and always at a
  /// phase's last item. Thread-safe.
  void count(const std::string& phase, std::size_t done, std::size_t total, const std::string& unit,
             const std::string& detail = "");
  /// "  <phase>  <percent> %  ETA <t>", for work known only as a fraction (0 to 1).
  void fraction(const std::string& phase, double f);
  /// Erases the line, if one may have been drawn.
  void clear();
  /// Writes `text` and a newline to stderr above the line (the line is erased first, then drawn
  /// again below): log lines and the progress line together. Plain when the line is off.
  void message(const std::string& text);

  /// ImportOptions::progress that draws on this line: "reading <file>  shapes|meshing  n %". With
  /// isolated readers it runs in the reader's child process, on the same terminal; the parent
  /// clears the line afterwards.
  std::function<void(const ImportProgress&)> import_progress(const std::string& file);

 private:
  void draw_locked(const std::string& line, bool force);
  void restart_locked(const std::string& phase);

  bool on_ = false;
  bool maybe_drawn_ = false;
  std::mutex mutex_;
  std::string phase_;
  std::chrono::steady_clock::time_point phase_start_{};
  std::chrono::steady_clock::time_point last_draw_{};
  std::string last_line_;  ///< what the line shows now
};

/// import_mesh() with a progress line while a CAD file is read (none when `quiet`).
Result<ImportedModel> import_mesh_with_progress(const std::string& file, ImportOptions options, bool quiet);

/// "12 s", "3 min 05 s", "2 h 10 min": a duration for a progress line.
std::string progress_duration(double seconds);

}  // namespace swept::cli
