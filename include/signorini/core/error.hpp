#pragma once
// Exceptions thrown by the library. Every message is one line that names what was wrong and what
// was expected, so that the command-line tool can print it as it is.

#include <stdexcept>
#include <string>

namespace signorini {

/// Bad input: a problem description, a mesh or an option that cannot be used.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A numerical failure that is not the user's fault (e.g. a factorisation of a matrix that
/// should be SPD failed).
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace signorini
