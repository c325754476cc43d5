#pragma once
// Process exit codes of every heartsim subcommand.
namespace hs::app {
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;    // could not write output, internal error
constexpr int kExitBadInput = 2;   // bad scenario, key, value, file or option
constexpr int kExitInvalidSimulation = 3;  // NaN, inverted tets
constexpr int kExitValidationFailed = 4;   // `validate` ran, but the result is outside its bound
}  // namespace hs::app
