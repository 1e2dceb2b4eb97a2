#pragma once
/// \file
/// `SceneMetrics` as JSON (one object, `dyop scene --json`) and as CSV rows (`dyop compare`).
/// Non-finite numbers are written as JSON `null` (CSV: empty), and such a record has
/// `nan_detected` true. The hash is written as 16 hexadecimal digits in a string: JSON numbers
/// lose integers above 2⁵³.
///
/// Box2D scenes add `skip_config`, the names of the skips the world ran with (an array, empty for
/// `--skip none`), and `skips`, an object counting the evaluations skipped per reason
/// (`{"bounds": n, "warm-axis": n}`); both are `null` for `paper`. In CSV an object
/// becomes one column per key (`skips.bounds`, ...) and an array one cell, its names separated by
/// spaces.
///
/// The `slide` scene adds `slide`: its sliding bodies' largest vertical and angular speeds
/// (`max_vertical_speed` m/s, `max_angular_speed` rad/s), their smallest travel fraction
/// (`min_travel`), and `sliders`, one object per slider (`body`, `ground`, `rolling`,
/// `max_vertical_speed`, `max_angular_speed`, `travel`); `null` for the other scenes. In CSV
/// the three figures are columns (`slide.max_vertical_speed`, ...); `sliders` is not (a list of
/// records: `dyop compare` writes it in `slide.csv`).

#include <iosfwd>
#include <string>
#include <vector>

#include "scenes/metrics.hpp"

namespace dyop::report {

/// The JSON object's keys, in the order written.
const std::vector<std::string>& metrics_keys();

/// The CSV columns: `metrics_keys`, with an object's key replaced by `key.sub` for each of its
/// keys.
const std::vector<std::string>& csv_columns();

/// One JSON object, indented, with a final newline.
void write_json(const scenes::SceneMetrics& m, std::ostream& out);

/// The CSV header: `csv_columns` joined by commas.
std::string csv_header();

/// One CSV line (no newline) in `csv_header` order; numbers with 9 significant digits.
std::string csv_row(const scenes::SceneMetrics& m);

/// The hash as written: 16 lower-case hexadecimal digits.
std::string hash_hex(std::uint64_t hash);

}  // namespace dyop::report
