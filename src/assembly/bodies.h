#pragma once
// Internal to swept_assembly: an assembly's parts as bodies of the contact layer (contact.h).
#include "swept/assembly/assembly.h"
#include "swept/assembly/disassemble.h"
#include "swept/contact/contact.h"

#include <vector>

namespace swept::assembly_detail {

/// The body of the given parts of `assembly` (merged in the given order), with its own tree.
inline contact::Body make_body(const Assembly& assembly, const std::vector<std::size_t>& parts,
                               const BuildConfig& config) {
  std::vector<const TriangleSoup*> soups;
  for (std::size_t i : parts) soups.push_back(&assembly.parts[i].mesh);
  return contact::make_body(soups, config);
}

/// find_interferences over bodies already made (one per part, at the mounted poses), for the
/// pairs with at least one part `among`.
std::vector<Interference> interferences(const std::vector<contact::Body>& bodies, double tolerance,
                                        const std::vector<bool>& among);

}  // namespace swept::assembly_detail
