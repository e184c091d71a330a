#pragma once
/// \file row_exact.hpp
/// Exact event-driven solution of rows of 1-D parts (issue 24, docs/rows.md): the contact core's
/// model (core/model.hpp) with SliderBody parts linked by PartContact, on a table whose
/// acceleration along e1 is piecewise constant (PiecewisePolynomialProfile, degree 0: the
/// paper's three-phase profiles, square waves), friction piecewise constant along the table
/// (a uniform field, or an AxisField of steps read at each part's leading edge: point
/// footprints) and Coulomb laws with static >= kinetic, direction-dependent.
///
/// Touching parts (a closed contact with zero relative velocity) form clusters. Between events
/// every cluster has a constant acceleration, so each arc is a parabola, closed-form; events
/// are located in closed form:
///   - the table's acceleration switches (exact by construction);
///   - a moving cluster's velocity reaches 0: t = -x'/x'' (eq. 21);
///   - two parts that do not touch collide: the first root of the gap's quadratic;
///   - a moving part reaches a friction boundary: a root of its quadratic.
/// At every event the mode of each cluster (which parts stick, slip forward or backward, split
/// off or push on together) is the unique solution of the chain problem at acceleration level
/// (core/chain_problem.hpp): exact stick at the part-table contacts, a split where the front
/// part's acceleration exceeds the rear's; never a velocity threshold. A collision is Newton's
/// impact law at the colliding contact, plastic at the contacts that already touch, and no
/// friction impulse (finite friction forces over zero time): the chain problem in the
/// velocities without friction; the mode problem follows.
///
/// Bouncing parts (restitution e > 0) pushed against each other collide ever faster, as a
/// bouncing ball: a collision whose incoming relative speed is below RowExactOptions::
/// bounce_resolution ends the accumulation as a plastic impact (the relative speed it drops is
/// below that bound).

#include <cstddef>
#include <span>
#include <vector>

#include "selfalign/core/chain_problem.hpp"
#include "selfalign/core/model.hpp"
#include "selfalign/simulate/motion_observer.hpp"

namespace selfalign {

struct RowExactOptions {
  /// A collision with incoming relative speed at or below this [-] is plastic (ends a bounce
  /// accumulation; e = 0 rows never bounce). >= 0.
  double bounce_resolution = 1e-12;
};

/// Counters of an exact row run.
struct RowExactStatistics {
  long long arcs = 0;          ///< arcs of the whole row (one per event)
  long long collisions = 0;    ///< impacts between parts
  long long separations = 0;   ///< touching parts split by the mode problem or an impact
  long long velocity_zeros = 0;
  long long boundaries = 0;    ///< friction boundaries crossed
};

/// The row's state: per body (the model's order) its leading edge x [-] and velocity x' [-]
/// relative to the table, and per part contact whether it touches (closed, zero relative
/// velocity); where it is in the table's profile and the friction pieces.
struct RowExactState {
  double t = 0;
  std::vector<double> x, v;
  std::vector<signed char> touching;   ///< per Model::part_contacts entry
  std::vector<std::size_t> piece;      ///< per body: its friction piece
  std::size_t segment = 0;
  long long period_index = 0;
  RowExactStatistics statistics;
  // workspace
  std::vector<double> a;               ///< per body: acceleration over the current arc
  /// Per body: where its current parabola starts (time, x, x'). A part's anchor moves only
  /// when its acceleration or velocity changes, so a part that touches no other moves bit for
  /// bit as it does alone (its arcs do not depend on the other parts' events).
  std::vector<double> t_anchor, x_anchor, v_anchor;
  std::vector<double> previous_a, v_before;
  std::vector<signed char> moved;      ///< per body: its velocity changed at the last event
  std::vector<double> zero_at, cross_at;  ///< per body: its velocity zero, next boundary [-]
  std::vector<signed char> direction;  ///< per body: its direction over the arc
  std::vector<core::ChainPart> parts;
  std::vector<core::ChainFriction> friction;
  std::vector<double> c, chain_v;
  std::vector<int> chain;
  core::ChainWorkspace work;
};

/// The state at time t with the parts at x (leading edges) and velocities v relative to the
/// table (one per body). Parts of a contact whose gap is 0 and whose velocities are equal start
/// touching. Throws InvalidParameter naming what the solver cannot take: "bodies[i]" (not a
/// SliderBody, a uniform footprint), "bodies[i].law" (velocity-dependent), "motion" (other than
/// a piecewise-constant acceleration along e1), "gravity", "field" (not uniform or an axis
/// field of steps increasing along e1), "x" / "v" (sizes, non-finite, overlapping parts:
/// "x[i]" names the front part); and what validate(core::Model) throws.
RowExactState make_row_exact_state(const core::Model& model, double t, std::span<const double> x,
                                   std::span<const double> v);

/// Advances the row to t_end (>= state.t). The observer (if any) gets each part's piece of every
/// arc (on_motion with `body` its index, nullptr arc; ArcEnd::part_contact where a collision
/// ended it). Returns the arcs computed.
std::size_t advance_row_exact(const core::Model& model, RowExactState& state, double t_end,
                              MotionObserver* observer = nullptr,
                              const RowExactOptions& options = {});

}  // namespace selfalign
