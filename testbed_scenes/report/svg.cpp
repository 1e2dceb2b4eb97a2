#include "report/svg.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace dyop::report {
namespace {

using scenes::Drawing;
using scenes::DrawShape;

const char* fill_of(DrawShape::Role r) {
  switch (r) {
    case DrawShape::Role::Static:
      return "#b0b0b0";
    case DrawShape::Role::Kinematic:
      return "#7fa7e0";
    case DrawShape::Role::Dynamic:
      return "#f3a35b";
  }
  return "#000000";
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

void write_svg(const Drawing& drawing, std::ostream& out) {
  // Bounding box in double; every coordinate is then written relative to its centre.
  double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x;
  double hi_x = -lo_x, hi_y = -lo_x;
  for (const DrawShape& s : drawing.shapes) {
    const double r = s.kind == DrawShape::Kind::Circle ? s.radius : 0;
    for (const Vec2<double>& p : s.points) {
      if (!std::isfinite(p.x()) || !std::isfinite(p.y())) continue;
      lo_x = std::min(lo_x, p.x() - r);
      hi_x = std::max(hi_x, p.x() + r);
      lo_y = std::min(lo_y, p.y() - r);
      hi_y = std::max(hi_y, p.y() + r);
    }
  }
  if (!(lo_x <= hi_x)) lo_x = lo_y = -1, hi_x = hi_y = 1;  // nothing finite to draw
  // Pixel coordinates (800 px wide), relative to the box's corner, y down: every renderer reads
  // them alike, and a scene 10 km away keeps its digits (the offset is taken in double first).
  const double margin = 0.05 * std::max({hi_x - lo_x, hi_y - lo_y, 1e-3});
  const double px = 800.0 / (hi_x - lo_x + 2 * margin);  // pixels per metre
  const double title = 36;                               // pixels
  const double height = (hi_y - lo_y + 2 * margin) * px + title;
  auto X = [&](double x) { return (x - lo_x + margin) * px; };
  auto Y = [&](double y) { return (hi_y + margin - y) * px + title; };
  auto R = [&](double r) { return r * px; };

  const auto old_precision = out.precision(6);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"" << std::ceil(height)
      << "\" viewBox=\"0 0 800 " << std::ceil(height) << "\">\n"
      << "<rect x=\"0\" y=\"0\" width=\"800\" height=\"" << std::ceil(height)
      << "\" fill=\"white\"/>\n"
      << "<text x=\"8\" y=\"24\" font-family=\"sans-serif\" font-size=\"15\">"
      << escape(drawing.title);
  out.precision(9);
  out << " (x " << lo_x << " to " << hi_x << " m, y " << lo_y << " to " << hi_y << " m)</text>\n";
  out.precision(6);
  // Translucent fills: overlapping shapes (the paper's kinematic triangles) stay visible.
  out << "<g stroke=\"#303030\" stroke-width=\"0.7\" stroke-linejoin=\"round\" "
         "fill-opacity=\"0.8\">\n";
  auto finite = [](const DrawShape& s) {
    return std::all_of(s.points.begin(), s.points.end(), [](const Vec2<double>& p) {
      return std::isfinite(p.x()) && std::isfinite(p.y());
    });
  };
  for (const DrawShape& s : drawing.shapes) {
    if (s.points.empty() || !finite(s)) continue;  // a NaN body is reported, not drawn
    switch (s.kind) {
      case DrawShape::Kind::Polygon:
        out << "<polygon fill=\"" << fill_of(s.role) << "\" points=\"";
        for (const Vec2<double>& p : s.points) out << X(p.x()) << ',' << Y(p.y()) << ' ';
        out << "\"/>\n";
        break;
      case DrawShape::Kind::Circle:
        out << "<circle fill=\"" << fill_of(s.role) << "\" cx=\"" << X(s.points[0].x())
            << "\" cy=\"" << Y(s.points[0].y()) << "\" r=\"" << R(s.radius) << "\"/>\n";
        if (s.points.size() > 1) {
          out << "<line x1=\"" << X(s.points[0].x()) << "\" y1=\"" << Y(s.points[0].y())
              << "\" x2=\"" << X(s.points[1].x()) << "\" y2=\"" << Y(s.points[1].y()) << "\"/>\n";
        }
        break;
      case DrawShape::Kind::Segment:
        if (s.points.size() > 1) {
          out << "<line stroke-width=\"2\" x1=\"" << X(s.points[0].x()) << "\" y1=\""
              << Y(s.points[0].y()) << "\" x2=\"" << X(s.points[1].x()) << "\" y2=\""
              << Y(s.points[1].y()) << "\"/>\n";
        }
        break;
    }
  }
  out << "</g>\n<g font-family=\"sans-serif\" font-size=\"14\" text-anchor=\"middle\" "
         "dominant-baseline=\"middle\">\n";
  for (const DrawShape& s : drawing.shapes) {
    if (s.label.empty() || s.points.empty() || !finite(s)) continue;
    Vec2<double> c = Vec2<double>::Zero();
    for (const Vec2<double>& p : s.points) c += p;
    c /= static_cast<double>(s.points.size());
    out << "<text x=\"" << X(c.x()) << "\" y=\"" << Y(c.y()) << "\">" << escape(s.label)
        << "</text>\n";
  }
  out << "</g>\n</svg>\n";
  out.precision(old_precision);
}

}  // namespace dyop::report
