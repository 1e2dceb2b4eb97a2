#include "report/viewer_page.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scenes/skips.hpp"

namespace dyop::report {

// The page's script and style (report/viewer/viewer.html), embedded by CMake.
extern const char* const viewer_html;

namespace {

using experiments::EdgeMark;
using experiments::LockstepRecording;
using experiments::ViewContact;
using experiments::ViewFrame;
using experiments::ViewManifold;

// Non-finite numbers (a world that blew up) go as 0, and magnitudes stay below 2^50 so that the
// predictions' sums stay exact in the page's doubles (2^53).
std::int64_t quantise(double v, double quantum) {
  constexpr double limit = 1e15;
  const double q = v / quantum;
  return std::isfinite(q) ? std::llround(std::clamp(q, -limit, limit)) : 0;
}

// Unsigned LEB128 varints; signed values zigzag-encoded first, so that small residuals of either
// sign take one byte.
class Varints {
 public:
  void put(std::uint64_t v) {
    while (v >= 0x80) {
      bytes_.push_back(char(0x80 | (v & 0x7f)));
      v >>= 7;
    }
    bytes_.push_back(char(v));
  }
  void put_signed(std::int64_t v) {
    put(v < 0 ? (std::uint64_t(-(v + 1)) << 1) | 1 : std::uint64_t(v) << 1);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

// The recording's streams, in the order the page reads their lengths: each holds one kind of
// number, so that deflate finds like next to like.
enum Stream : int {
  PosePosition,
  PoseAngle,
  Structure,
  Normal,
  LocalPoint,
  Clip,
  Separation,
  Key,
  stream_count
};

// A number of a contact, and the stream it goes to. A separation is predicted from the
// manifold's geometry at the step's quantised poses (`predicted_separation`), every other number
// from the same pair's one step before.
struct Value {
  Stream stream;
  std::int64_t value;
};

// A manifold's numbers in the order the page reads them: the local normal's angle, the local
// point, then per point its local point, separation and key.
void append_values(const ViewManifold& m, std::vector<Value>& v) {
  v.push_back({Normal, quantise(std::atan2(m.local_normal.y, m.local_normal.x), angle_quantum)});
  v.push_back({LocalPoint, quantise(m.local_point.x, local_quantum)});
  v.push_back({LocalPoint, quantise(m.local_point.y, local_quantum)});
  for (int i = 0; i < m.points; ++i) {
    v.push_back({Clip, quantise(m.point[i].local.x, local_quantum)});
    v.push_back({Clip, quantise(m.point[i].local.y, local_quantum)});
    v.push_back({Separation, quantise(m.point[i].separation, separation_quantum)});
    v.push_back({Key, m.point[i].key});
  }
}

// A body's quantised pose as the page holds it: position, cosine and sine.
struct Placement {
  double x, y, c, s;
  // A body-frame point in the world (the page's `worldPoint`, operation for operation).
  std::array<double, 2> apply(double px, double py) const {
    return {x + c * px - s * py, y + s * px + c * py};
  }
};

// What `b2WorldManifold::Initialize` makes the separation of a manifold's point from its
// quantised numbers `q` (as `append_values` lays them out, the point's local point at
// `q[at]`, `q[at + 1]`) and the bodies' placements: the page computes the same, operation for
// operation, so that only the difference to the recorded separation travels (a few quanta where
// the poses' rounding moved the bodies, instead of each contact's millimetres per step).
double predicted_separation(ViewManifold::Reference reference, const std::vector<std::int64_t>& q,
                            std::size_t first, std::size_t at, const Placement& a,
                            const Placement& b, double ra, double rb) {
  const std::array<double, 2> lp = {double(q[first + 1]) * local_quantum,
                                    double(q[first + 2]) * local_quantum};
  const std::array<double, 2> local = {double(q[at]) * local_quantum,
                                       double(q[at + 1]) * local_quantum};
  if (reference == ViewManifold::Reference::Circles) {
    const std::array<double, 2> pa = a.apply(lp[0], lp[1]), pb = b.apply(local[0], local[1]);
    const double dx = pb[0] - pa[0], dy = pb[1] - pa[1];
    return std::sqrt(dx * dx + dy * dy) - ra - rb;
  }
  const bool face_a = reference == ViewManifold::Reference::FaceA;
  const Placement& ref = face_a ? a : b;
  const Placement& inc = face_a ? b : a;
  const double angle = double(q[first]) * angle_quantum;
  const double ln_x = std::cos(angle), ln_y = std::sin(angle);
  const double nx = ref.c * ln_x - ref.s * ln_y, ny = ref.s * ln_x + ref.c * ln_y;
  const std::array<double, 2> plane = ref.apply(lp[0], lp[1]);
  const std::array<double, 2> clip = inc.apply(local[0], local[1]);
  const double d = (clip[0] - plane[0]) * nx + (clip[1] - plane[1]) * ny;
  return d - ra - rb;
}

// A pose number from the last two steps, at constant velocity (a body falling or gliding costs
// nothing); the first step from zero, the second from the first.
std::int64_t predicted_pose(int step, std::int64_t last, std::int64_t before) {
  return step == 0 ? 0 : step == 1 ? last : 2 * last - before;
}

// Rounds half up, as the page's Math.floor(x + 0.5).
std::int64_t round_half_up(double x) { return std::int64_t(std::floor(x + 0.5)); }

// Bits 0-1 point count, 2-3 reference (Circles, FaceA, FaceB), 4-6 reference edge; the plug-in's
// manifold in bits 0-6, Box2D's (marked contacts) in bits 10-16; bits 7-8 the mark, bit 9 agrees.
std::uint64_t manifold_flags(const ViewManifold& m) {
  return std::uint64_t(m.points) | std::uint64_t(m.reference) << 2 |
         std::uint64_t(m.reference_edge) << 4;
}

std::uint64_t contact_flags(const ViewContact& c) {
  return manifold_flags(c.manifold) | std::uint64_t(c.mark) << 7 | std::uint64_t(c.agrees) << 9 |
         (c.mark != EdgeMark::None ? manifold_flags(c.box2d) << 10 : 0);
}

// One runner's frames into the streams, each value as its residual from a prediction the page
// makes alike.
class RunnerEncoder {
 public:
  explicit RunnerEncoder(const LockstepRecording& recording) : recording_(recording) {}

  void encode(const ViewFrame& frame, std::array<Varints, stream_count>& streams) {
    const std::size_t n = frame.poses.size() * 3;
    std::vector<std::int64_t> now(n);
    for (std::size_t b = 0; b < frame.poses.size(); ++b) {
      now[3 * b] = quantise(frame.poses[b].x, position_quantum);
      now[3 * b + 1] = quantise(frame.poses[b].y, position_quantum);
      now[3 * b + 2] = quantise(frame.poses[b].angle, angle_quantum);
    }
    last_.resize(n, 0);
    before_.resize(n, 0);
    std::vector<Placement> placed(frame.poses.size());
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t predicted = predicted_pose(steps_, last_[i], before_[i]);
      streams[i % 3 == 2 ? PoseAngle : PosePosition].put_signed(now[i] - predicted);
      before_[i] = last_[i];
      last_[i] = now[i];
    }
    for (std::size_t b = 0; b < placed.size(); ++b) {
      const double angle = double(now[3 * b + 2]) * angle_quantum;
      placed[b] = {double(now[3 * b]) * position_quantum, double(now[3 * b + 1]) * position_quantum,
                   std::cos(angle), std::sin(angle)};
    }
    ++steps_;

    Varints& structure = streams[Structure];
    structure.put(frame.contacts.size());
    std::map<std::pair<int, int>, std::vector<std::int64_t>> seen;
    int previous_a = 0;
    for (const ViewContact& c : frame.contacts) {
      structure.put(std::uint64_t(c.fixture_a - previous_a));  // sorted: never negative
      structure.put_signed(c.fixture_b - c.fixture_a);
      structure.put(contact_flags(c));
      previous_a = c.fixture_a;
      std::vector<Value> v;
      append_values(c.manifold, v);
      if (c.mark != EdgeMark::None) append_values(c.box2d, v);
      const std::pair<int, int> key{c.fixture_a, c.fixture_b};
      const auto before = previous_.find(key);
      std::vector<std::int64_t>& kept = seen[key];
      for (const Value& x : v) kept.push_back(x.value);
      const experiments::ViewFixture& fa = recording_.fixtures[c.fixture_a];
      const experiments::ViewFixture& fb = recording_.fixtures[c.fixture_b];
      std::size_t first = 0;  // where the current manifold's numbers begin
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (i > 0 && v[i].stream == Normal) first = i;
        std::int64_t predicted = 0;
        if (v[i].stream == Separation) {
          const ViewManifold& m = first == 0 ? c.manifold : c.box2d;
          predicted =
              round_half_up(predicted_separation(m.reference, kept, first, i - 2, placed[fa.body],
                                                 placed[fb.body], fa.radius, fb.radius) /
                            separation_quantum);
        } else if (before != previous_.end() && i < before->second.size()) {
          predicted = before->second[i];
        }
        streams[v[i].stream].put_signed(v[i].value - predicted);
      }
    }
    previous_ = std::move(seen);
  }

 private:
  const LockstepRecording& recording_;
  int steps_ = 0;
  std::vector<std::int64_t> last_, before_;
  // Each pair's values one step before (pairs absent then are predicted as zeros).
  std::map<std::pair<int, int>, std::vector<std::int64_t>> previous_;
};

std::string deflate(const std::string& raw) {
  uLongf size = compressBound(raw.size());
  std::string out(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(out.data()), &size,
                reinterpret_cast<const Bytef*>(raw.data()), raw.size(), 9) != Z_OK) {
    throw std::runtime_error("zlib could not compress the recording");
  }
  out.resize(size);
  return out;
}

std::string base64(const std::string& bytes) {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto byte = [&](std::size_t at) {
      return at < bytes.size() ? std::uint32_t(std::uint8_t(bytes[at])) : 0u;
    };
    const std::uint32_t n = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    out += alphabet[n >> 18 & 63];
    out += alphabet[n >> 12 & 63];
    out += i + 1 < bytes.size() ? alphabet[n >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? alphabet[n & 63] : '=';
  }
  return out;
}

// The frames, both runners step by step, as the page decodes them.
std::string encoded_frames(const LockstepRecording& r) {
  std::array<Varints, stream_count> streams;
  RunnerEncoder runner[2] = {RunnerEncoder(r), RunnerEncoder(r)};
  for (int step = 0; step < r.steps; ++step) {
    for (int k = 0; k < 2; ++k) runner[k].encode(r.frames[k][step], streams);
  }
  Varints header;
  std::string body;
  for (const Varints& s : streams) {
    header.put(s.bytes().size());
    body += s.bytes();
  }
  return base64(deflate(header.bytes() + body));
}

int marked(const ViewFrame& f) {
  int n = 0;
  for (const ViewContact& c : f.contacts) n += c.mark != EdgeMark::None;
  return n;
}

Json page_data(const LockstepRecording& r) {
  Json d = viewer_summary(r);
  Json roles = Json::array();
  for (scenes::DrawShape::Role role : r.bodies) roles.push_back(int(role));
  d["roles"] = roles;
  Json fixtures = Json::array();
  for (const experiments::ViewFixture& f : r.fixtures) {
    Json points = Json::array();
    for (const b2Vec2& p : f.points) {  // to 1e-5 m: a sliver's 1 cm is drawn true
      points.push_back(double(quantise(p.x, 1e-5)) * 1e-5);
      points.push_back(double(quantise(p.y, 1e-5)) * 1e-5);
    }
    Json fixture = {f.body, int(f.kind), points, f.radius, f.side};
    if (f.appears != 0 || f.disappears >= 0) {  // a ground edited while recorded
      fixture.push_back(f.appears);
      fixture.push_back(f.disappears);
    }
    fixtures.push_back(fixture);
  }
  d["fixture_shapes"] = fixtures;
  d["quanta"] = {{"position", position_quantum},
                 {"local", local_quantum},
                 {"angle", angle_quantum},
                 {"separation", separation_quantum}};
  d["agreement_tolerance"] = experiments::agreement_tolerance;
  d["redirect_angle"] = experiments::redirect_angle;
  d["data"] = encoded_frames(r);
  return d;
}

}  // namespace

Json viewer_summary(const LockstepRecording& r) {
  Json s;
  s["scene"] = r.scene;
  s["seed"] = r.seed;
  s["steps"] = r.steps;
  s["time_step"] = r.time_step;
  s["runners"] = {scenes::name(r.runners[0]), scenes::name(r.runners[1])};
  s["skips"] = {scenes::skip_argument(r.configs[0]), scenes::skip_argument(r.configs[1])};
  s["internal_edges"] = {r.configs[0].internal_edges, r.configs[1].internal_edges};
  s["recycle_distance"] = {r.configs[0].recycle_distance, r.configs[1].recycle_distance};
  s["bodies"] = r.bodies.size();
  s["fixtures"] = r.fixtures.size();
  Json frames = Json::array();
  for (int step = 0; step < r.steps; ++step) {
    Json touching = Json::array(), agreeing = Json::array(), marks = Json::array(),
         penetration = Json::array(), collide = Json::array();
    for (int k = 0; k < 2; ++k) {
      const ViewFrame& f = r.frames[k][step];
      touching.push_back(f.touching);
      agreeing.push_back(f.agreeing);
      marks.push_back(marked(f));
      penetration.push_back(f.max_penetration);
      collide.push_back(f.collide_ms);
    }
    frames.push_back({{"step", step + 1},
                      {"touching", touching},
                      {"agreeing", agreeing},
                      {"marked", marks},
                      {"max_penetration", penetration},
                      {"collide_ms", collide}});
  }
  s["frames"] = frames;
  return s;
}

std::string viewer_page_file(const std::string& name) { return "view_" + name + ".html"; }

void write_viewer_page(const LockstepRecording& recording, std::ostream& out) {
  std::string json = page_data(recording).dump();
  // Inside a <script> element nothing may close it.
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at)) {
    json.replace(at, 2, "<\\/");
  }
  const std::string page = viewer_html;
  const std::string slot = "{{RECORDING}}";
  const std::size_t at = page.find(slot);
  out << page.substr(0, at) << json << page.substr(at + slot.size());
}

}  // namespace dyop::report
