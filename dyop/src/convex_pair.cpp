#include "dyop/convex_pair.hpp"

#include "detail/polygon_circle.hpp"
#include "detail/polygon_pair.hpp"

namespace dyop {
template <class T>
Result<T> collide(const Polygon<T>& pa, const Polygon<T>& pb, const ConvexQuery<T>& q) {
  return detail::collide_polygons(pa, pb, q);
}

template <class T>
Result<T> collide(const Polygon<T>& pa, const Circle<T>& circle, const ConvexQuery<T>& q) {
  return detail::collide_polygon_circle(pa, circle, q);
}

template <class T>
Result<T> collide(const Segment<T>& sa, const Polygon<T>& pb, const ConvexQuery<T>& q) {
  return detail::collide_polygons(sa, pb, q);
}

template <class T>
Result<T> collide(const Segment<T>& sa, const Circle<T>& circle, const ConvexQuery<T>& q) {
  return detail::collide_polygon_circle(sa, circle, q);
}

template Result<float> collide(const Segment<float>&, const Polygon<float>&,
                               const ConvexQuery<float>&);
template Result<double> collide(const Segment<double>&, const Polygon<double>&,
                                const ConvexQuery<double>&);
template Result<float> collide(const Segment<float>&, const Circle<float>&,
                               const ConvexQuery<float>&);
template Result<double> collide(const Segment<double>&, const Circle<double>&,
                                const ConvexQuery<double>&);
template Result<float> collide(const Polygon<float>&, const Polygon<float>&,
                               const ConvexQuery<float>&);
template Result<double> collide(const Polygon<double>&, const Polygon<double>&,
                                const ConvexQuery<double>&);
template Result<float> collide(const Polygon<float>&, const Circle<float>&,
                               const ConvexQuery<float>&);
template Result<double> collide(const Polygon<double>&, const Circle<double>&,
                                const ConvexQuery<double>&);

}  // namespace dyop
