// The coordinate count of a multibody tree as a compile-time constant for the short dense loops
// over it (the dof-space solve, the planar mass matrix): f(std::integral_constant<int, N>) with N
// the count for 1–12 coordinates, N = 0 (the count known only when running) beyond. The loops
// then unroll; they do the same arithmetic in the same order either way. Internal to physics/.
#pragma once

#include <type_traits>

namespace gearsim::physics {

template <typename F>
decltype(auto) with_dof_count(int dofs, F&& f) {
  switch (dofs) {
    case 1:
      return f(std::integral_constant<int, 1>{});
    case 2:
      return f(std::integral_constant<int, 2>{});
    case 3:
      return f(std::integral_constant<int, 3>{});
    case 4:
      return f(std::integral_constant<int, 4>{});
    case 5:
      return f(std::integral_constant<int, 5>{});
    case 6:
      return f(std::integral_constant<int, 6>{});
    case 7:
      return f(std::integral_constant<int, 7>{});
    case 8:
      return f(std::integral_constant<int, 8>{});
    case 9:
      return f(std::integral_constant<int, 9>{});
    case 10:
      return f(std::integral_constant<int, 10>{});
    case 11:
      return f(std::integral_constant<int, 11>{});
    case 12:
      return f(std::integral_constant<int, 12>{});
    default:
      return f(std::integral_constant<int, 0>{});
  }
}

}  // namespace gearsim::physics
