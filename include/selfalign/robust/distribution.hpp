#pragma once
/// \file distribution.hpp
/// What is known about one uncertain input of a process (a friction coefficient, c_mu, a width,
/// the rough region's start, the table's amplitude or period): exactly its nominal value, a
/// normal distribution (optionally truncated), a uniform distribution, a list of measured
/// samples (drawn with equal weight), or only an interval.
///
/// Monte-Carlo draws use the inverse CDF of a uniform number u in (0, 1) (quantile()), so one
/// u per run and input makes a run's inputs a pure function of (seed, run, input): results do
/// not depend on the thread count or on how runs are split into chunks. An Interval has no
/// probability: Monte Carlo treats it as uniform (and says so); worst-case searches use its
/// bounds (box()).

#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace selfalign {

/// Known exactly: the nominal value given elsewhere (the design request's).
struct Known {};
/// Normal(mean, sd) truncated to [lower, upper] (infinite bounds: not truncated).
struct Normal {
  double mean = 0, sd = 0;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
};
/// Uniform on [lower, upper].
struct Uniform {
  double lower = 0, upper = 0;
};
/// Measured values, each drawn with probability 1/n.
struct Samples {
  std::vector<double> values;
};
/// Only bounds are known: worst-case analyses search [lower, upper]; Monte Carlo draws it
/// uniformly.
struct Interval {
  double lower = 0, upper = 0;
};

using Distribution = std::variant<Known, Normal, Uniform, Samples, Interval>;

/// Throws InvalidParameter naming `name` (e.g. "mu.sd") when the distribution is not usable:
/// a negative or non-finite standard deviation, bounds that exclude the mean or are reversed,
/// an empty or non-finite sample list, a reversed interval.
void validate(const std::string& name, const Distribution& d);

/// Its nominal value: the mean of a normal, the midpoint of a uniform or interval, the mean of
/// the samples; `known` for Known.
double nominal(const Distribution& d, double known);

/// The value at probability u in (0, 1): inverse CDF (a normal's truncated to its bounds; the
/// samples' empirical one: values sorted, index floor(u n)). Known gives `known`.
double quantile(const Distribution& d, double u, double known);

/// The range a worst-case search covers: the bounds of a uniform, interval or sample list; a
/// normal's truncation bounds, each replaced by mean -/+ `sigmas` sd where infinite.
std::pair<double, double> box(const Distribution& d, double known, double sigmas);

/// True unless Known.
bool is_uncertain(const Distribution& d);

/// One line, e.g. "normal(mean=0.2, sd=0.01)", "known", "samples(n=12)".
std::string describe(const Distribution& d);

/// Parses the command-line / config text of a distribution (docs/robust-design.md):
///   "normal:MEAN,SD[,LOWER,UPPER]"  "normal:MEAN,SD%"  (SD as a percentage of MEAN)
///   "uniform:LOWER,UPPER"  "interval:LOWER,UPPER"  "samples:V1,V2,..."  "known"
/// Throws InvalidParameter naming `name` on malformed text or invalid values.
Distribution parse_distribution(const std::string& name, const std::string& text);

}  // namespace selfalign
