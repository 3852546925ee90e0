#pragma once
// The errors glintlab throws, which the CLI maps to its exit codes (README.md, "Use"):
// InputError -> 2 (bad usage or input), RuntimeFailure -> 1 (failure at run time). Part of the
// installed interface: the C++ library and the Python module raise the CLI's messages unchanged.
#include <stdexcept>
#include <string>

namespace glintlab {

/// Bad user input: the message names the file, key or line, the value and what is allowed.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Something failed at run time (GL context, driver, disk, NaN in a result).
class RuntimeFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace glintlab
