#pragma once
/// \file error.hpp
/// The one exception type of selfalign's API edge: a parameter outside its allowed range.
///
/// Expected outcomes (a non-physical "case 0" profile, a run that sticks) are values the caller
/// branches on; misuse (a negative width, c_mu <= 1, NaN) throws InvalidParameter.

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace selfalign {

/// A parameter outside its allowed range. what() is one short line:
/// "invalid <name> = <value>: <allowed>", e.g. "invalid width = -1: must be > 0"; a value longer
/// than 100 characters is shown by its head and tail, and line breaks become spaces. value()
/// keeps it whole.
class InvalidParameter : public std::invalid_argument {
 public:
  InvalidParameter(std::string name, std::string value, std::string allowed);
  InvalidParameter(std::string name, double value, std::string allowed);

  const std::string& name() const noexcept { return name_; }
  const std::string& value() const noexcept { return value_; }
  const std::string& allowed() const noexcept { return allowed_; }

 private:
  std::string name_, value_, allowed_;
};

/// Formats a double the way error messages and JSON summaries print it (shortest round-trip).
std::string format_number(double value);

/// Throws InvalidParameter unless value is finite and > 0.
double require_positive(std::string_view name, double value);
/// Throws InvalidParameter unless value is finite and >= 0.
double require_non_negative(std::string_view name, double value);
/// The number `text` spells (std::stod, the whole text; "nan" and "inf" parse); throws
/// InvalidParameter(name, text, "must be a number") otherwise.
double parse_number(const std::string& name, const std::string& text);
/// Throws InvalidParameter unless value is finite.
double require_finite(std::string_view name, double value);
/// Throws InvalidParameter unless value is finite and > bound ("must be > bound").
double require_greater(std::string_view name, double value, double bound);
/// The largest magnitude selfalign accepts for a free-valued input (a velocity, a position, a
/// config number): dimensionless quantities of this model are O(1e-6 .. 1e6), and 1e50 keeps
/// products of several such quantities (energies, y = a t^2/2, (k w)^2 A) finite.
inline constexpr double kMaxMagnitude = 1e50;
/// Throws InvalidParameter unless value is finite and |value| <= kMaxMagnitude.
double require_moderate(std::string_view name, double value);
/// Throws InvalidParameter unless 1/kMaxMagnitude <= value <= kMaxMagnitude (a positive scale:
/// a width, a length, a limit), the positive counterpart of require_moderate.
double require_positive_moderate(std::string_view name, double value);
/// Throws InvalidParameter unless value is finite and lo < value <= hi.
double require_in_half_open(std::string_view name, double value, double lo, double hi);

/// A library parameter's name and the name its user gave it (a flag, a config key, a file's
/// key), so that a message names what the user typed: {"accels", "accelerations"},
/// {"load_fractions", "part.loads"}.
struct UserName {
  std::string_view library, user;
};

/// `e` naming what the user gave: each comma-separated part of its name ("mu_static,
/// mu_kinetic") that is a library name of `names`, or such a name with an index ("accels[2]"),
/// becomes the user's name (with the same index); other parts get `prefix` before them
/// (e.g. "table.x." for a file's section) unless they already start with it. Value and allowed
/// range are kept.
InvalidParameter renamed(const InvalidParameter& e, std::span<const UserName> names,
                         std::string_view prefix = {});

/// Runs `f()`, and rethrows an InvalidParameter it throws as renamed(e, names, prefix): the
/// one place a front end maps the library's parameter names to its own.
template <class F>
decltype(auto) with_user_names(std::span<const UserName> names, F&& f,
                               std::string_view prefix = {}) {
  try {
    return f();
  } catch (const InvalidParameter& e) {
    throw renamed(e, names, prefix);
  }
}

}  // namespace selfalign
