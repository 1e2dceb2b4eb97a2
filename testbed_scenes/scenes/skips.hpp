#pragma once
/// \file
/// `--skip`: the switches of `box2d::Config` by name, as `dyop scene` and `dyop compare` take
/// them and as the reports write them. Names: "bounds" (`bounds_early_out`), "warm-axis",
/// "lin-canny-cache"; "all" and "none" for every one.

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "dyop/box2d.hpp"

namespace dyop::scenes {

/// One switch of `box2d::Config`.
struct SkipSwitch {
  const char* name;            ///< its `--skip` name
  bool box2d::Config::*field;  ///< the `Config` field it sets
  const char* what;            ///< one line: what is skipped
};

/// Number of switches: the fields of `box2d::Config`.
inline constexpr int skip_switch_count = 3;

// A skip added to `box2d::Config` needs its switch below (`internal_edges`, `recycle_distance`
// and `triangles_only`, the three more fields, are not skips: they change the answer). The
// layout `Config` has with exactly these fields:
struct ConfigFields {
  bool skips[skip_switch_count];
  bool internal_edges;
  float recycle_distance;
  bool triangles_only;
};
static_assert(sizeof(box2d::Config) == sizeof(ConfigFields),
              "every box2d::Config skip has a --skip switch");

/// Every switch, in `box2d::Config`'s field order.
inline const std::array<SkipSwitch, skip_switch_count>& skip_switches() {
  static const std::array<SkipSwitch, skip_switch_count> list = {{
      {"bounds", &box2d::Config::bounds_early_out,
       "pairs whose bounding circles are apart beyond reach get no axis work"},
      {"warm-axis", &box2d::Config::warm_axis,
       "last step's face tried first: when it still separates beyond reach, no other work"},
      {"lin-canny-cache", &box2d::Config::lin_canny_cache,
       "lin-canny starts from last step's features (no effect on the other backends)"},
  }};
  return list;
}

/// What `parse_skips` made of a `--skip` argument.
struct ParsedSkips {
  box2d::Config config;  ///< valid when `ok()`
  std::string error;     ///< empty, or why the text is not a skip list, naming the bad word
  bool ok() const { return error.empty(); }  ///< true when `error` is empty
};

/// A `--skip` argument: "all" (`Config::all()`), "none" (`Config::no_skips()`), or a
/// comma-separated list of switch names (those on, the others off; repeats allowed). An unknown or
/// empty name is an error.
inline ParsedSkips parse_skips(std::string_view text) {
  ParsedSkips out;
  if (text == "all") return out;
  out.config = box2d::Config::no_skips();
  if (text == "none") return out;
  const auto& switches = skip_switches();
  for (std::size_t begin = 0;;) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string_view word = text.substr(begin, end - begin);
    const auto hit = std::find_if(switches.begin(), switches.end(),
                                  [&](const SkipSwitch& s) { return word == s.name; });
    if (hit == switches.end()) {
      out.error = (word.empty() ? std::string("empty skip name")
                                : "unknown skip '" + std::string(word) + "'") +
                  " in '" + std::string(text) + "' (all, none, or a comma-separated list of:";
      for (const SkipSwitch& s : switches) {
        out.error += std::string(&s == &switches.front() ? " " : ", ") + s.name;
      }
      out.error += ")";
      return out;
    }
    out.config.*(hit->field) = true;
    if (end == text.size()) return out;
    begin = end + 1;
  }
}

/// The names of the switches on in `config`, in `skip_switches` order.
inline std::vector<std::string> skip_names(const box2d::Config& config) {
  std::vector<std::string> names;
  for (const SkipSwitch& s : skip_switches()) {
    if (config.*(s.field)) names.emplace_back(s.name);
  }
  return names;
}

/// `config` as a `--skip` argument: "all", "none", or the names of those on, comma-separated.
inline std::string skip_argument(const box2d::Config& config) {
  const std::vector<std::string> names = skip_names(config);
  if (names.empty()) return "none";
  if (names.size() == skip_switches().size()) return "all";
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}

/// The `--skip` option's help: the syntax and one line per switch.
inline std::string skip_help() {
  std::string help =
      "Narrow-phase work the Box2D world may skip: all (default), none, or a comma-separated "
      "list of";
  for (const SkipSwitch& s : skip_switches()) help += std::string("\n  ") + s.name + ": " + s.what;
  return help + "\n(the paper scene has no Box2D world: nothing to skip)";
}

}  // namespace dyop::scenes
