#pragma once
// A user's own interface model from a shared library (issue 22 item 6): a UMAT-style entry point,
// C or Fortran (every argument by reference), loaded at run time and then driven, compared with
// DEM, mapped and assessed like any built-in model. README.md in this folder.
//
//   void NAME(double stress[3], double statev[NSTATV], double ddsdde[9], const double stran[3],
//             const double dstran[3], const int* nstatv, const double props[NPROPS],
//             const int* nprops, double* pnewdt);
//
// stress: (normal, shear x, shear y), tension positive (Abaqus' sign); stran, dstran: (eps_n
// opening positive, gamma_x, gamma_y) total and increment; ddsdde: d stress / d dstran, column
// major (Fortran: DDSDDE(i, j) = d stress_i / d dstran_j); pnewdt < 1 asks for a smaller increment.
#include <string>

#include "models/registry.hpp"

namespace iwb::models {

// The spec of the model `entry` in `library` (dlopen; `entry` or gfortran's `entry_`), named
// `entry`. Its parameter files hold a table [external]: nstatv (0-10) and the PROPS p1 (or p01),
// p2, ... InputError naming the library or the entry; a bad table is refused when the model is
// made.
ModelSpec external_model_spec(const std::string& library, const std::string& entry);

}  // namespace iwb::models
