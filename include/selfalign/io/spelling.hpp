#pragma once
/// \file spelling.hpp
/// "Did you mean ...?": the name a user most likely meant when the one typed is unknown (a
/// config key, a planar section's key, a subcommand, a flag).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace selfalign {

/// The Levenshtein distance between a and b (insertions, deletions, substitutions); names
/// longer than 64 characters count as far from everything (SIZE_MAX).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate `name` is most likely a typo of: the closest within 2 edits, '_' and '-'
/// and letter case not counted (`c_mu` is `c-mu`, `SIMULATE` is `simulate`); empty when none
/// is that close, or when name is too short (at most 2 characters) for a guess to mean anything.
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace selfalign
