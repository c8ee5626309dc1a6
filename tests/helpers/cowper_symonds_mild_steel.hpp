// The tests' one Swift x Cowper-Symonds set: Cowper & Symonds' (1957) mild-steel rate constants
// (D = 40.4 /s, q = 5) on an illustrative Swift hardening (K = 530 MPa, eps0 = 0.01, n = 0.26).
#pragma once

#include "models/flow_stress/cowper_symonds.hpp"

namespace impact::testing {

inline CowperSymondsParams cowper_symonds_mild_steel() {
  CowperSymondsParams p;
  p.K = 530e6;
  p.eps0 = 0.01;
  p.n = 0.26;
  p.D = 40.4;
  p.q = 5.0;
  return p;
}

}  // namespace impact::testing
