#pragma once
/// \file model.hpp
/// The contact core's model (issue 21): immutable and runtime-sized, in the spirit of MuJoCo's
/// mjModel. Bodies on one moving table, each of a closed set of kinds (a variant): a rigid part
/// in the plane (inertia, contact patch in the body frame) or the paper's 1-D part (one
/// translational coordinate and its friction level); each with the friction law of its surface
/// pair with the table; the table's planar motion (planar_table_motion.hpp) and friction field
/// (planar_field.hpp), its normal motion with gravity and the incline (Gravity); the time step.
/// The number of bodies is a runtime value. Flight after a lift-off is Gravity::flight's
/// (Moreau-Jean); otherwise the step reports lift_off and stops. Part-part contacts: between
/// 1-D parts of a row (PartContact, issue 24; docs/rows.md) and between planar parts with
/// outlines (OutlineContact: discs and convex polygons, planar/outline.hpp).

#include <optional>
#include <variant>
#include <vector>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/planar/outline.hpp"
#include "selfalign/planar/planar_field.hpp"
#include "selfalign/planar/rigid_part.hpp"
#include "selfalign/planar/planar_table_motion.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign::core {

/// A rigid part in the table's plane: pose (x, y, angle) and twist on the table. Its step
/// stages read the model's field at its patch points (src/planar/rigid_body_step.hpp).
struct RigidBody {
  RigidPart part;       ///< inertia j = I/(m L^2) [-] and contact patch (body frame)
  FrictionLaw law{};    ///< body-table law: isotropic, velocity-independent (planar solvers)
  double mass = 1;      ///< m / m_ref [-], in (0, 1e50]: ratios between bodies in contact
  /// Its outline (OutlineContact): a disc or a convex polygon about the centre of mass, body
  /// frame [-]; NoOutline: it touches no other part.
  Outline outline{};
};

/// The paper's 1-D part (Sect. 3) as a body: one translational coordinate x [-] relative to the
/// table along the table's first motion axis e1 (in its state: pose.x = x, twist.ux = x'; the
/// other coordinates stay 0; its leading edge at x e1 on the table), its contact footprint and
/// any FrictionLaw (static above kinetic, direction-dependent, Stribeck, viscous). Its level is
/// the model's field read along e1 and averaged over the footprint [x - w, x] (eq. 7): exactly,
/// for a uniform field or an AxisField (the 1-D FrictionField's window integral), and at the
/// point x e1 for the other fields, which take a point footprint only. Its step is the 1-D
/// Moreau step (time_stepping.hpp), the one function the 1-D stepper runs, with the table's
/// velocity along e1. Needs a table that does not turn.
/// In a row (Model::part_contacts) the part is the segment [x - length, x] along e1 with mass
/// `mass` (a lone part's motion does not depend on either: friction scales with the weight).
struct SliderBody {
  Footprint footprint = PointFootprint{};  ///< along e1 (friction_field.hpp)
  FrictionLaw law{};
  double mass = 1;    ///< m / m_ref [-], in (0, 1e50]: the ratio between touching parts' masses
  double length = 0;  ///< the part's length along e1 [-] behind its leading edge x (a row: > 0)
};

/// One body on the table (a closed set: each kind's stages are one visitor's alternatives).
using Body = std::variant<RigidBody, SliderBody>;

/// Gravity on a table whose plane is inclined, and which may move along its normal (the loads
/// stage of core/step.hpp). Without it (Model::gravity empty: the paper's model) each body
/// presses on the table with its weight, the unit of the friction levels, and nothing pulls it
/// along the plane. With it, over a step from t_k to t_{k+1} each body receives, per unit mass,
///   the normal impulse   h g cos(incline) + (z'(t_{k+1}) - z'(t_k))   (the table pushes it
///                        up with the table's normal velocity change; z from motion.normal),
///   gravity's impulse    h g sin(incline) along `downhill`, in the table's plane,
/// and its friction impulses are bounded by s m (resp. k m) times the normal impulse over g:
/// the paper's h s m at incline 0 without normal motion. A step whose normal impulse is
/// negative lifts the bodies off (the table falls away faster than gravity): without `flight`
/// the step sets status lift_off and the run stops there. With `flight` (Moreau-Jean, a
/// unilateral normal contact per body, docs/feeder.md): each body has a height above the table
/// and its rate (BodyState::height, normal_velocity); over a step its free normal velocity is
/// w - h g cos(incline) - (z'(t_{k+1}) - z'(t_k)); where the height at the step's midpoint is
/// <= 0 and that velocity is negative the contact is active and takes the plastic normal
/// impulse P = -(free velocity) (restitution 0: the body ends the step at the table's normal
/// velocity), otherwise the body flies (P = 0, no friction impulse); the friction impulses are
/// bounded by s m P / g, k m P / g, and the height moves by the theta rule. A body resting on
/// the table gets P = g (h cos(incline) + Δz'/g), the load above, up to rounding.
struct Gravity {
  /// g in the model's acceleration unit [-] (> 0): in the paper's dimensionless units, where
  /// accelerations are in units of mu_1 g, g = 1 / mu_1.
  double g = 1;
  double incline = 0;                      ///< the plane's angle to the horizontal, [0, pi/2) [rad]
  double downhill_x = 1, downhill_y = 0;   ///< the plane's steepest descent, unit, world axes
  bool flight = false;  ///< lift-off and landing by Moreau-Jean (false: stop at a lift-off)
  /// Newton's restitution e at a landing, in [0, 1] (0: plastic): Moreau-Jean's active contact
  /// drives the relative normal velocity to -e times the step's incoming one.
  double restitution = 0;
};

/// A unilateral contact between two 1-D parts of a row (issue 24, docs/rows.md): `rear` and
/// `front` index Model::bodies (both SliderBody); the gap (x_front - length_front) - x_rear
/// stays >= 0 (the parts cannot pass each other). Moreau's step treats the contact as active
/// where the gap at the step's midpoint is <= 0 and asks the relative velocity at t_{k+1} for
/// at least -e times the incoming one (Newton's restitution e; 0: plastic, the parts push on
/// together). The touching parts of a row are one chain problem per step
/// (core/chain_problem.hpp): Coulomb friction with exact stick at each part-table contact.
struct PartContact {
  int rear = 0, front = 1;
  double restitution = 0;  ///< e in [0, 1]
};

/// A unilateral contact between two planar parts with outlines (RigidBody::outline: discs and
/// convex polygons; issue 24, docs/rows.md section 10): the outlines do not overlap. At each
/// step the contact's manifold (planar/outline.hpp: one point, or two for parallel faces) is
/// found at the step's midpoint poses; the contact is active where its smallest gap is <= 0,
/// and then each of its points carries a unilateral normal impulse (Newton's restitution e on
/// the normal relative velocity where the point touches; where it is still apart, the
/// speculative bound that it may close its gap by the step's end) and a Coulomb tangential
/// impulse `friction` between the parts. The bodies' patch friction with the table keeps its exact stick (block
/// Gauss-Seidel: each body's patch problem solved exactly for the impulses of its contacts,
/// each point's impulse projected on its cone).
struct OutlineContact {
  int a = 0, b = 1;
  double restitution = 0;  ///< e in [0, 1]
  double friction = 0.5;   ///< Coulomb coefficient between the parts, >= 0
};

struct Model {
  PlanarTableMotion motion;                 ///< borrowed profiles: they must outlive the model
  PlanarField field = UniformPlanarField{};
  std::vector<Body> bodies;                 ///< N >= 1, a runtime value
  TimeSteppingOptions options;              ///< Moreau's step h [-] and theta
  /// Gravity, incline and the normal load (empty: the paper's model, a constant normal load;
  /// a motion with a normal profile needs it).
  std::optional<Gravity> gravity{};
  /// Contacts between 1-D parts (rows). Each body is the rear of at most one contact and the
  /// front of at most one, the contacts form chains (no cycle), and the parts of a contact
  /// have a length > 0 and a velocity-independent law. Empty: the bodies never touch.
  std::vector<PartContact> part_contacts{};
  /// Contacts between planar parts with outlines (rigid bodies); empty: none.
  std::vector<OutlineContact> outline_contacts{};
};

/// Throws InvalidParameter naming the first invalid part ("gravity.g", "gravity.incline",
/// "gravity.downhill" (not a unit vector), "motion.normal" without gravity; "bodies" when there are none;
/// "bodies[i].inertia", "bodies[i].law" for body i; for a slider "bodies[i].footprint" (a width
/// outside [1e-50, 1e50], or a uniform footprint on a field other than uniform or axis) and
/// "bodies[i].motion" (a table that turns), "bodies[i].mass", "bodies[i].length" (not > 0 in
/// a row), "bodies[i].law" (velocity-dependent in a row); "part_contacts[j]" (an index out of
/// range, a body that is not a 1-D part, a body in two contacts on one side, a cycle),
/// "part_contacts[j].restitution"; for a rigid body "bodies[i].mass", "bodies[i].radius",
/// "bodies[i].outline" (outline.hpp's checks); "outline_contacts[j]" (an index out of range,
/// not a rigid body, a == b), "bodies[i].outline" (a body of a contact without one),
/// "outline_contacts[j].restitution" and "outline_contacts[j].friction").
void validate(const Model& model);

/// The gap (x_front - length_front) - x_rear of part contact `contact` with its parts' leading
/// edges at x_rear and x_front [-] (>= 0: the parts do not overlap).
double part_gap(const Model& model, const PartContact& contact, double x_rear, double x_front);

/// The level m(x) of slider `body` of `model` at x along e1 (SliderBody: the field along e1,
/// averaged over the footprint) [-].
double slider_level(const Model& model, const SliderBody& body, double x);

}  // namespace selfalign::core
