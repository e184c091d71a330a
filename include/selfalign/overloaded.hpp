#pragma once
/// \file overloaded.hpp
/// The visitor of a closed set held in a std::variant: one lambda per alternative,
///   std::visit(Overloaded{[](const A&) {...}, [](const B&) {...}}, v).

namespace selfalign {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace selfalign
