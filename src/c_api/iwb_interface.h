/* iwb_interface.h: the interface models of the interface workbench as a C library
 * (libiwb_interface.so, pkg-config iwb_interface), for finite-element codes and other programs
 * (seed chapter 7: a stress point per interface integration point, a virtual thickness d_s^v).
 *
 * Conventions (iwb's CONVENTIONS.md):
 *   - relative displacement increment du = (du_n, du_x, du_y): du_n > 0 opens the interface; the
 *     strain increment is du / d_s^v (eps_n, gamma_x, gamma_y; gamma engineering shear). With
 *     d_s^v = 1 the increments are strains.
 *   - traction t = (sigma_n, tau_x, tau_y) in kPa, sigma_n compression positive.
 *   - tangent: d t_i / d du_j, row-major 3x3, kPa per unit of du (per unit strain when d_s^v = 1);
 *     the exact derivative of the integrated increment (automatic differentiation through the
 *     stress-point integrator), not a finite difference and not the continuum tangent.
 *   - state: a flat array of iwb_state_size() doubles with named components (iwb_state_name).
 *
 * Errors are status codes with a message copied into the caller's buffer (never an exit, never an
 * exception across the boundary). A material is immutable after creation: calls on one material
 * from several threads are safe; the library has no global mutable state.
 */
#ifndef IWB_INTERFACE_H
#define IWB_INTERFACE_H

#include <stddef.h>

#if defined(__GNUC__)
#define IWB_API __attribute__((visibility("default")))
#else
#define IWB_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef enum iwb_status {
  IWB_OK = 0,
  IWB_ERROR_INPUT = 1,       /* unknown model, bad parameter file, key, value or initial state */
  IWB_ERROR_DOMAIN = 2,      /* the increment left the model's domain: cut it (step_factor) */
  IWB_ERROR_CONVERGENCE = 3, /* the stress point did not converge: cut the increment */
  IWB_ERROR_INTERNAL = 4     /* anything else (a bug): the message says what */
} iwb_status;

typedef struct iwb_material iwb_material;

/* Version of the library, "MAJOR.MINOR.PATCH". */
IWB_API const char* iwb_version(void);

/* A material from a model name (`iwb models`) and a parameter file (TOML, data/params/). kappa_r is
 * the wall roughness for models that take it (1: fully rough; continuum models must be given 1).
 * integration: the stress-point integrator as the TOML text of a test file's [integration] table
 * ("scheme = \"euler\"\nsubsteps = 4", or "rtol = 1e-8"); NULL or "": adaptive rk32, rtol 1e-6.
 * On error *out is NULL and message holds why. */
IWB_API iwb_status iwb_material_create(const char* model, const char* parameter_file,
                                       double kappa_r, const char* integration, iwb_material** out,
                                       char* message, size_t message_size);

/* The same from n parameters given as "table.key" = value ("hypoplastic.phi_c_deg" = 30). */
IWB_API iwb_status iwb_material_create_from_values(const char* model, const char* const* keys,
                                                   const double* values, int n, double kappa_r,
                                                   const char* integration, iwb_material** out,
                                                   char* message, size_t message_size);

IWB_API void iwb_material_destroy(iwb_material* material);

/* 1 if only the model's monotonic part is built (Mortara's outer surface, without the surface
 * that acts where the path reverses): a caller whose path reverses should refuse it. 0 otherwise,
 * and for NULL. */
IWB_API int iwb_monotonic_only(const iwb_material* material);

IWB_API int iwb_state_size(const iwb_material* material);
/* Name of state component i ("T_n", "e", "p_c", ...), valid while the material lives; NULL if out
 * of range. */
IWB_API const char* iwb_state_name(const iwb_material* material, int i);
/* Number of the model's declared initial inputs and the key of input i ("sigma_n_kPa", "e0", "K0",
 * "OCR"). */
IWB_API int iwb_initial_input_count(const iwb_material* material);
IWB_API const char* iwb_initial_input_key(const iwb_material* material, int i);

/* The initial state from n inputs by key (as a test file's [initial]: "sigma_n_kPa", "e0", "K0",
 * "OCR", ...); undeclared keys are refused, missing ones take the model's defaults. */
IWB_API iwb_status iwb_initial_state(const iwb_material* material, const char* const* keys,
                                     const double* values, int n, double* state, char* message,
                                     size_t message_size);

/* The traction of a state. */
IWB_API iwb_status iwb_traction(const iwb_material* material, const double* state,
                                double traction[3], char* message, size_t message_size);

/* One increment: state_in and du (with the virtual thickness d_s^v > 0; a model whose law is in
 * displacement, as hyperbolic, mortara and api-tz, takes du over its own d_s and ignores d_s^v) ->
 * state_out, traction and
 * (if tangent is not NULL) the consistent tangent. dt and external (temperature, suction, time
 * increments; NULL when the model reads none) are passed to models that declare them. On
 * IWB_ERROR_DOMAIN or IWB_ERROR_CONVERGENCE state_out is state_in and *step_factor < 1 suggests the
 * fraction of du to retry with (as Abaqus' PNEWDT); on success *step_factor is 1. step_factor may
 * be NULL. state_out may alias state_in. */
IWB_API iwb_status iwb_update(const iwb_material* material, const double* state_in,
                              const double du[3], double thickness, double dt,
                              const double* external, double* state_out, double traction[3],
                              double* tangent, double* step_factor, char* message,
                              size_t message_size);

#ifdef __cplusplus
}
#endif

#endif /* IWB_INTERFACE_H */
