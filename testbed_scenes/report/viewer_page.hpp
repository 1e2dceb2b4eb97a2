#pragma once
/// \file
/// `dyop view`'s page: one self-contained HTML file (inline script and style, no network) that
/// plays a `LockstepRecording` back: both worlds side by side or overlaid, contacts coloured by
/// agreement, the plug-in's differences from `b2CollidePolygons` marked, a click on a contact
/// shows its numbers, per-step plots under the view. The script and style are
/// `report/viewer/viewer.html`, embedded at build time.
///
/// The recording travels in the page compressed: every pose, normal, point and separation
/// quantised to an integer (`position_quantum`, ...) and predicted: poses linearly from the last
/// two steps (a falling or gliding body costs nothing); a manifold kept as Box2D keeps it, in its
/// bodies' frames (`localNormal`, `localPoint`, each point's `localPoint`), from the same pair's
/// numbers one step before (a resting contact costs nothing either; the page places it from the
/// poses as `b2WorldManifold::Initialize` does); a separation from the manifold's geometry at
/// the quantised poses. The residuals go as zigzag varints into one stream per kind of number
/// (so that deflate finds like next to like), deflated with zlib and base64-encoded; the page
/// inflates them with the browser's `DecompressionStream("deflate")` and predicts alike.
///
/// The page shows step N (1-based: the world after N steps) and pauses there when opened with
/// `#step=N` in its address (`&view=overlay` overlays the worlds; `x`, `y`, `scale` set the
/// camera; `select=A-B` or `select=deepest` opens a contact's numbers). It writes what it shows
/// into elements a test can read: `#step`, `#bodies-a`/`-b`, `#contacts-a`/`-b` (touching
/// contacts), `#agree-a`/`-b`, `#marked-a`/`-b` (contacts with an `EdgeMark`),
/// `#penetration-a`/`-b` (mm), `#details` (the selected contact's numbers), `#errors` (every
/// script error; empty when none) and `#status` ("ready" once the first frame is drawn).

#include <iosfwd>
#include <string>

#include "experiments/lockstep_recording.hpp"
#include "report/json.hpp"

namespace dyop::report {

/// Quanta of the page's numbers. Why: a tenth of a millimetre and 1e-4 rad (0.1 mm at the rim of
/// a 1 m body) are below a pixel until a body fills the window, and a 1 cm sliver's contacts stay
/// within 1 % of it. Separations keep the same tenth of a millimetre, a tenth of the agreement
/// tolerance: the numbers a click shows are this close; agreement, the marks and `--json` are
/// decided on the full numbers. Finer quanta cost more than they show: at 1e-5, a pile's jitter
/// makes `rain-tall`'s page 40 % larger.
inline constexpr double position_quantum = 1e-4;    ///< m, poses
inline constexpr double local_quantum = 1e-4;       ///< m, manifold points in a body's frame
inline constexpr double angle_quantum = 1e-4;       ///< rad, poses and normals
inline constexpr double separation_quantum = 1e-4;  ///< m

/// The file name of `dyop compare`'s viewer page of a recording called `name`:
/// "view_<name>.html".
std::string viewer_page_file(const std::string& name);

/// Writes the page for `recording`.
void write_viewer_page(const experiments::LockstepRecording& recording, std::ostream& out);

/// What the page shows per step, for `dyop view --json` and the browser test: the scene, the
/// runners, the body and fixture counts, and per step each runner's touching, agreeing and marked
/// contacts, largest penetration (m) and `b2Profile::collide` (ms).
Json viewer_summary(const experiments::LockstepRecording& recording);

}  // namespace dyop::report
