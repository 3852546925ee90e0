#pragma once
// The `glintlab` command line: render, compare, animate, bench, converge, view, the listings, report and the precompute reports.
namespace glintlab {

/// Parses and runs; returns the exit code (0 ok, 2 bad usage or input, 1 failure at run time).
int run_cli(int argc, char** argv);

}  // namespace glintlab
