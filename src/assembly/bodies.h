#pragma once
// Internal to swept_assembly: an assembly's parts as bodies of the contact layer (contact.h).
#include "swept/assembly/assembly.h"
#include "swept/assembly/disassemble.h"
#include "swept/contact/contact.h"

#include <chrono>
#include <functional>
#include <mutex>
#include <vector>

namespace swept::assembly_detail {

/// The body of the given parts of `assembly` (merged in the given order), with its own tree.
inline contact::Body make_body(const Assembly& assembly, const std::vector<std::size_t>& parts,
                               const BuildConfig& config) {
  std::vector<const TriangleSoup*> soups;
  for (std::size_t i : parts) soups.push_back(&assembly.parts[i].mesh);
  return contact::make_body(soups, config);
}

/// Reports progress (DisassemblyOptions::progress) from parallel work: one call at a time, at
/// most every 0.1 s within a phase, and always for its last item.
class ProgressReporter {
 public:
  explicit ProgressReporter(const std::function<void(const DisassemblyProgress&)>& sink) : sink_(sink) {}
  bool enabled() const { return static_cast<bool>(sink_); }
  /// One more item of `phase` done out of `total`; thread-safe.
  void step(const char* phase, std::size_t total);
  /// `done` of `total` items of `phase` (a new phase restarts the count).
  void set(const char* phase, std::size_t done, std::size_t total);

 private:
  const std::function<void(const DisassemblyProgress&)>& sink_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  const char* phase_ = nullptr;
  std::size_t done_ = 0;
  double last_s_ = -1.0;
  void report_locked(std::size_t total);
};

/// find_interferences over bodies already made (one per part, at the mounted poses), for the
/// pairs with at least one part `among`; each pair checked is a step of "interferences".
std::vector<Interference> interferences(const std::vector<contact::Body>& bodies, double tolerance,
                                        const std::vector<bool>& among, ProgressReporter* progress = nullptr);

}  // namespace swept::assembly_detail
