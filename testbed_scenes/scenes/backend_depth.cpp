#include "scenes/backend_depth.hpp"

#include "box2d_reference/collide_triangles.hpp"
#include "dyop/method.hpp"

namespace dyop::scenes {

Result<float> backend_depth(box2d::Backend backend, const Triangle<float>& a,
                            const Triangle<float>& b, LinCannyCache* cache) {
  const Query<float> depth{Level::Depth};
  switch (backend) {
    case box2d::Backend::Dyop: return penetrate(Method::Dyop, a, b, depth);
    case box2d::Backend::DyopFast: return penetrate(Method::DyopFast, a, b, depth);
    case box2d::Backend::LinCanny: return penetrate(Method::LinCanny, a, b, depth, cache);
    case box2d::Backend::Sat: return penetrate(Method::Sat, a, b, depth);
    case box2d::Backend::Epa: return penetrate(Method::Epa, a, b, depth);
    case box2d::Backend::Box2D: return box2d::collide_triangles(a, b);
  }
  return {};
}

}  // namespace dyop::scenes
