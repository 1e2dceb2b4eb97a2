#pragma once
/// \file
/// A scene's drawing (`scenes/drawing.hpp`) as SVG, written by hand (no dependency), centred on
/// the shapes' bounding box so that a scene 10 km from the origin draws as sharply as one at the
/// origin.

#include <iosfwd>

#include "scenes/drawing.hpp"

namespace dyop::report {

/// The drawing as a standalone SVG document, 800 px wide.
void write_svg(const scenes::Drawing& drawing, std::ostream& out);

}  // namespace dyop::report
