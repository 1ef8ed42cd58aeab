#pragma once
/// The CLI's output helpers (aligned tables, number formatting, output files written whole) are
/// the ones the benchmarks use: swept/bench/output.h, brought into swept::cli.
#include "swept/bench/output.h"

namespace swept::cli {

using bench::fmt_fixed;
using bench::fmt_int;
using bench::fmt_sci;
using bench::json_text;
using bench::Table;
using bench::valid_utf8;
using bench::write_output;

}  // namespace swept::cli
