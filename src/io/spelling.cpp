#include "selfalign/io/spelling.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

namespace selfalign {
namespace {

constexpr std::size_t kMaxLength = 64;   // longer names are no typo of a flag or key
constexpr std::size_t kMaxEdits = 2;     // a typo: a swapped, missing or extra letter or two

std::string normalised(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  if (a.size() > kMaxLength || b.size() > kMaxLength) return std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string closest_name(std::string_view name, const std::vector<std::string>& candidates) {
  const std::string n = normalised(name);
  if (n.size() <= 2) return {};
  std::string best;
  std::size_t best_distance = kMaxEdits + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(n, normalised(c));
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

}  // namespace selfalign
