// The contact-core model's parameter view (core/parameters.hpp): each parameter is a slot, a
// getter and a setter on a mutable, decomposed copy of the model (Flat), which compose() turns
// back into a Model, so that the laws and an axis field are rebuilt (and checked) once, after
// every value is set.

#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "selfalign/core/parameters.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/spelling.hpp"
#include "selfalign/overloaded.hpp"

namespace selfalign::core {
namespace {

// A law's numbers (FrictionLaw's getters); stribeck_velocity NaN: no decay.
struct LawNumbers {
  double s, kf, kb, stribeck, exponent, viscous;
};

LawNumbers numbers_of(const FrictionLaw& l) {
  return {l.static_coefficient(), l.kinetic_forward(),   l.kinetic_backward(),
          l.stribeck_velocity() > 0 ? l.stribeck_velocity() : NAN, l.stribeck_exponent(),
          l.viscous()};
}

FrictionLaw law_of(const LawNumbers& n) {
  FrictionLaw law(n.s, n.kf, n.kb);
  if (!std::isnan(n.stribeck)) law = law.with_stribeck(n.stribeck, n.exponent);
  if (n.viscous != 0) law = law.with_viscous(n.viscous);
  return law;
}

const FrictionLaw& law_of_body(const Body& b) {
  return std::visit([](const auto& body) -> const FrictionLaw& { return body.law; }, b);
}

// The model as numbers that can be set one by one.
struct Flat {
  Model model;
  std::vector<LawNumbers> laws;  // one per body
  std::vector<FieldNode> nodes;  // an axis field's nodes (empty otherwise)
};

Flat flatten(const Model& m) {
  Flat f{m, {}, {}};
  for (const Body& b : m.bodies) f.laws.push_back(numbers_of(law_of_body(b)));
  if (const auto* a = std::get_if<AxisField>(&m.field))
    f.nodes.assign(a->field.nodes().begin(), a->field.nodes().end());
  return f;
}

Model compose(Flat f) {
  for (std::size_t i = 0; i < f.model.bodies.size(); ++i) {
    const std::string at = "bodies[" + std::to_string(i) + "].law";
    try {
      const FrictionLaw law = law_of(f.laws[i]);
      std::visit([&law](auto& body) { body.law = law; }, f.model.bodies[i]);
    } catch (const InvalidParameter& e) {
      throw InvalidParameter(at + "." + e.name(), e.value(), e.allowed());
    }
  }
  if (auto* a = std::get_if<AxisField>(&f.model.field)) {
    try {
      a->field = FrictionField(f.nodes);
    } catch (const InvalidParameter& e) {
      throw InvalidParameter("field." + e.name(), e.value(), e.allowed());
    }
  }
  validate(f.model);
  return std::move(f.model);
}

struct Slot {
  ModelParameter parameter;  // its value: the model's as given
  std::function<void(Flat&, double)> set;
};

class Slots {
 public:
  explicit Slots(Flat& flat) : flat_(flat) {}
  // A slot whose value is the number `ref` refers to, and whose setter writes through it.
  void add(std::string name, Dimension d, const char* group, std::string meaning,
           std::function<double&(Flat&)> ref) {
    const double value = ref(flat_);
    add(std::move(name), d, group, std::move(meaning), value,
        [ref](Flat& f, double v) { ref(f) = v; });
  }
  void add(std::string name, Dimension d, const char* group, std::string meaning, double value,
           std::function<void(Flat&, double)> set) {
    const bool angle = name.ends_with("angle") || name.ends_with("incline");
    slots.push_back({{std::move(name), value, d, angle ? "[rad]" : "[-]", group,
                      std::move(meaning)},
                     std::move(set)});
  }
  std::vector<Slot> slots;

 private:
  Flat& flat_;
};

using D = Dimension;

void add_law(Slots& s, const Flat& flat, std::size_t i, bool slider) {
  const std::string at = "bodies[" + std::to_string(i) + "].law.";
  s.add(at + "static", D::none, "law", "static coefficient s [mu_1]",
        [i](Flat& f) -> double& { return f.laws[i].s; });
  if (!slider) {  // isotropic: one kinetic coefficient, both directions
    s.add(at + "kinetic", D::none, "law", "kinetic coefficient k [mu_1] (both directions)",
          flat.laws[i].kf, [i](Flat& f, double v) { f.laws[i].kf = f.laws[i].kb = v; });
    return;
  }
  s.add(at + "kinetic", D::none, "law", "kinetic coefficient of forward slip k_+ [mu_1]",
        [i](Flat& f) -> double& { return f.laws[i].kf; });
  s.add(at + "kinetic_backward", D::none, "law", "kinetic coefficient of backward slip k_- [mu_1]",
        [i](Flat& f) -> double& { return f.laws[i].kb; });
  s.add(at + "stribeck_velocity", D::velocity, "law", "Stribeck velocity v_s (NaN: no decay)",
        [i](Flat& f) -> double& { return f.laws[i].stribeck; });
  if (!std::isnan(flat.laws[i].stribeck))
    s.add(at + "stribeck_exponent", D::none, "law", "Stribeck exponent delta",
          [i](Flat& f) -> double& { return f.laws[i].exponent; });
  s.add(at + "viscous", D::rate, "law", "viscous coefficient c",
        [i](Flat& f) -> double& { return f.laws[i].viscous; });
}

void add_bodies(Slots& s, const Flat& flat) {
  for (std::size_t i = 0; i < flat.model.bodies.size(); ++i) {
    const std::string at = "bodies[" + std::to_string(i) + "].";
    std::visit(
        Overloaded{[&](const RigidBody&) {
                     add_law(s, flat, i, false);
                     s.add(at + "inertia", D::none, "body", "j = I / (m L^2)",
                           [i](Flat& f) -> double& {
                             return std::get<RigidBody>(f.model.bodies[i]).part.inertia;
                           });
                   },
                   [&](const SliderBody& b) {
                     add_law(s, flat, i, true);
                     if (std::holds_alternative<UniformFootprint>(b.footprint))
                       s.add(at + "width", D::length, "body", "footprint width w",
                             [i](Flat& f) -> double& {
                               return std::get<UniformFootprint>(
                                          std::get<SliderBody>(f.model.bodies[i]).footprint)
                                   .width;
                             });
                   }},
        flat.model.bodies[i]);
  }
}

// A field kind's plain numbers: (name, member) pairs of the alternative F.
template <class F>
void add_members(Slots& s, std::initializer_list<std::pair<const char*, double F::*>> members) {
  for (const auto& entry : members) {
    const std::string n = entry.first;
    const auto member = entry.second;  // a variable (not a structured binding) to capture
    const D d = n == "c_mu" || n == "angle" || n == "level" ? D::none : D::length;
    s.add("field." + n, d, "field", n == "c_mu" ? "mu_2 / mu_1" : n,
          [member](Flat& f) -> double& { return std::get<F>(f.model.field).*member; });
  }
}

void add_field(Slots& s, const Flat& flat) {
  std::visit(
      Overloaded{
          [&](const UniformPlanarField&) {
            add_members<UniformPlanarField>(s, {{"level", &UniformPlanarField::level}});
          },
          [&](const HalfPlaneStepField&) {
            using F = HalfPlaneStepField;
            add_members<F>(s, {{"origin_x", &F::origin_x}, {"origin_y", &F::origin_y},
                               {"angle", &F::angle}, {"width", &F::width}, {"c_mu", &F::c_mu}});
          },
          [&](const StripField&) {
            using F = StripField;
            add_members<F>(s, {{"origin_x", &F::origin_x}, {"origin_y", &F::origin_y},
                               {"angle", &F::angle}, {"half_width", &F::half_width},
                               {"width", &F::width}, {"c_mu", &F::c_mu}});
          },
          [&](const RectangularPocketField&) {
            using F = RectangularPocketField;
            add_members<F>(s, {{"centre_x", &F::centre_x}, {"centre_y", &F::centre_y},
                               {"angle", &F::angle}, {"half_length", &F::half_length},
                               {"half_width", &F::half_width}, {"width", &F::width},
                               {"c_mu", &F::c_mu}});
          },
          [&](const CircularPocketField&) {
            using F = CircularPocketField;
            add_members<F>(s, {{"centre_x", &F::centre_x}, {"centre_y", &F::centre_y},
                               {"radius", &F::radius}, {"width", &F::width}, {"c_mu", &F::c_mu}});
          },
          [&](const GridField& g) {
            using F = GridField;
            add_members<F>(s, {{"origin_x", &F::origin_x}, {"origin_y", &F::origin_y},
                               {"angle", &F::angle}, {"dx", &F::dx}, {"dy", &F::dy}});
            for (std::size_t k = 0; k < g.levels.size(); ++k)
              s.add("field.levels[" + std::to_string(k) + "]", D::none, "field",
                    "cell level [mu_1]", [k](Flat& f) -> double& {
                      return std::get<GridField>(f.model.field).levels[k];
                    });
          },
          [&](const AxisField&) {
            using F = AxisField;
            add_members<F>(s, {{"origin_x", &F::origin_x}, {"origin_y", &F::origin_y},
                               {"angle", &F::angle}});
            for (std::size_t k = 0; k < flat.nodes.size(); ++k) {
              const std::string at = "[" + std::to_string(k) + "]";
              s.add("field.positions" + at, D::length, "field", "node position along the axis",
                    [k](Flat& f) -> double& { return f.nodes[k].position; });
              if (flat.nodes[k].left == flat.nodes[k].right)
                s.add("field.levels" + at, D::none, "field", "level at the node [mu_1]",
                      flat.nodes[k].right,
                      [k](Flat& f, double v) { f.nodes[k].left = f.nodes[k].right = v; });
              else {
                s.add("field.left" + at, D::none, "field", "level just before the jump [mu_1]",
                      [k](Flat& f) -> double& { return f.nodes[k].left; });
                s.add("field.right" + at, D::none, "field", "level from the jump on [mu_1]",
                      [k](Flat& f) -> double& { return f.nodes[k].right; });
              }
            }
          }},
      flat.model.field);
}

// The slots of `flat` (read through, not changed).
std::vector<Slot> slots_of(Flat& flat) {
  Slots s(flat);
  add_bodies(s, flat);
  add_field(s, flat);
  if (flat.model.gravity) {
    s.add("gravity.g", D::acceleration, "gravity", "g (1 / mu_1 in the paper's units)",
          [](Flat& f) -> double& { return f.model.gravity->g; });
    s.add("gravity.incline", D::none, "gravity", "the table plane's angle to the horizontal",
          [](Flat& f) -> double& { return f.model.gravity->incline; });
  }
  return std::move(s.slots);
}

}  // namespace

std::vector<ModelParameter> model_parameters(const Model& model) {
  validate(model);
  std::vector<ModelParameter> out;
  Flat flat = flatten(model);
  for (Slot& s : slots_of(flat)) out.push_back(std::move(s.parameter));
  return out;
}

Model with_parameters(const Model& model, const ParameterValues& values) {
  validate(model);
  Flat flat = flatten(model);
  const std::vector<Slot> slots = slots_of(flat);
  for (const auto& [name, value] : values) {
    const Slot* slot = nullptr;
    for (const Slot& s : slots)
      if (s.parameter.name == name) slot = &s;
    if (!slot) {
      std::vector<std::string> names;
      for (const Slot& s : slots) names.push_back(s.parameter.name);
      const std::string hint = closest_name(name, names);
      throw InvalidParameter(name, "unknown",
                             "is not a parameter of this model" +
                                 (hint.empty() ? std::string() : " (did you mean " + hint + "?)"));
    }
    if (!std::isfinite(value) && !(std::isnan(value) && name.ends_with(".stribeck_velocity")))
      throw InvalidParameter(name, value, "must be finite");
    slot->set(flat, value);
  }
  return compose(std::move(flat));
}

}  // namespace selfalign::core
