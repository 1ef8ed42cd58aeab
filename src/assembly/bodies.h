#pragma once
// Internal to swept_assembly: an assembly's parts as bodies of the contact layer (contact.h).
#include "swept/assembly/assembly.h"
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

}  // namespace swept::assembly_detail
