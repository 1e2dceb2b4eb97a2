// The paper experiment's methods: each behind the harness's one signature, and their names.
#include "box2d_reference/collide_triangles.hpp"
#include "dyop/dyop.hpp"
#include "dyop/dyop_paper.hpp"
#include "dyop/epa.hpp"
#include "dyop/lin_canny.hpp"
#include "dyop/sat.hpp"
#include "scenes/paper_harness.hpp"

namespace dyop::scenes::paper {
namespace {

// The paper asks for penetration depths: pairs apart need only the proof (`Apart::Gap`).
constexpr Query<float> kDepth{Level::Depth, 0, 0, Apart::Gap};

Result<float> run_dyop(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::dyop(a, b, kDepth);
}
Result<float> run_dyop_fast(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::dyop_fast(a, b, kDepth);
}
Result<float> run_dyop_paper(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::dyop_paper(a, b, kDepth);
}
Result<float> run_lin_canny_warm(const Triangle<float>& a, const Triangle<float>& b,
                                 LinCannyCache* cache) {
  return dyop::lin_canny(a, b, kDepth, cache);
}
Result<float> run_lin_canny_cold(const Triangle<float>& a, const Triangle<float>& b,
                                 LinCannyCache*) {
  return dyop::lin_canny(a, b, kDepth);
}
Result<float> run_sat(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::sat(a, b, kDepth);
}
Result<float> run_epa(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::epa(a, b, kDepth);
}
Result<float> run_box2d(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return box2d::collide_triangles(a, b);
}

}  // namespace

Fn fn_of(Method m) {
  switch (m) {
    case Method::Dyop: return run_dyop;
    case Method::DyopFast: return run_dyop_fast;
    case Method::DyopPaper: return run_dyop_paper;
    case Method::LinCannyWarm: return run_lin_canny_warm;
    case Method::LinCannyCold: return run_lin_canny_cold;
    case Method::Sat: return run_sat;
    case Method::Epa: return run_epa;
    case Method::Box2D: return run_box2d;
  }
  return run_sat;
}

const char* name(Method m) {
  switch (m) {
    case Method::Dyop: return "dyop";
    case Method::DyopFast: return "dyop-fast";
    case Method::DyopPaper: return "dyop-paper";
    case Method::LinCannyWarm: return "lin-canny-warm";
    case Method::LinCannyCold: return "lin-canny-cold";
    case Method::Sat: return "sat";
    case Method::Epa: return "epa";
    case Method::Box2D: return "box2d";
  }
  return "unknown";
}

Method method_of(box2d::Backend backend) {
  switch (backend) {
    case box2d::Backend::Dyop: return Method::Dyop;
    case box2d::Backend::DyopFast: return Method::DyopFast;
    case box2d::Backend::LinCanny: return Method::LinCannyWarm;
    case box2d::Backend::Sat: return Method::Sat;
    case box2d::Backend::Epa: return Method::Epa;
    case box2d::Backend::Box2D: return Method::Box2D;
  }
  return Method::Sat;
}

}  // namespace dyop::scenes::paper
