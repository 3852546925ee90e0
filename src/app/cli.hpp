#pragma once
// The `glintlab` command line: subcommands render, compare, animate, bench, methods, scenes, info.
namespace glintlab {

/// Parses and runs; returns the exit code (0 ok, 2 bad usage or input, 1 failure at run time).
int run_cli(int argc, char** argv);

}  // namespace glintlab
