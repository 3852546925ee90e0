#pragma once
// The error classes live in the installed interface (include/glintlab/error.hpp), so that a program
// linking glintlab catches the same types the CLI maps to its exit codes.
#include "glintlab/error.hpp"
