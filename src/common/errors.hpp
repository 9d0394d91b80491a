#pragma once
// Errors are values with context (STYLE.md): an input error names the file, the key, the value
// and what was allowed; a domain error names where the state left the model's domain.
#include <stdexcept>
#include <string>

namespace iwb {

// Bad user input: a file, key or value that cannot be used. The message is complete and meant to
// be shown to the user as it is.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A state left the constitutive model's domain (tension, e outside [e_d, e_i], NaN, outside the
// limit surface). Carries the message built where the violation was detected; the driver adds the
// increment.
class DomainError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The numerical method could not meet its tolerance (step size underflow, Newton divergence).
class ConvergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace iwb
