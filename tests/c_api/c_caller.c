/* A plain C caller of libiwb_interface (tests/c_api): the CV element test of cv_hvwe_euler.toml
 * through iwb_update, one line "gamma,sigma_n,tau" per increment on stdout, for
 * compare_with_element.py to hold against `iwb element`. Usage: c_caller PARAMETER_FILE */
#include <stdio.h>
#include <stdlib.h>

#include "iwb_interface.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: c_caller PARAMETER_FILE\n");
    return 2;
  }
  char message[1024];
  iwb_material* m = NULL;
  if (iwb_material_create("hvwe", argv[1], 1.0, "scheme = \"euler\"\nsubsteps = 4", &m, message, sizeof message) != IWB_OK) {
    fprintf(stderr, "c_caller: %s\n", message);
    return 1;
  }
  const char* keys[] = {"sigma_n_kPa", "e0"};
  const double values[] = {100.0, 0.7};
  double state[16], traction[3], tangent[9], factor;
  if (iwb_initial_state(m, keys, values, 2, state, message, sizeof message) != IWB_OK) {
    fprintf(stderr, "c_caller: %s\n", message);
    return 1;
  }
  const double du[3] = {0.0, 0.05 / 100, 0.0};
  for (int k = 1; k <= 100; ++k) {
    if (iwb_update(m, state, du, 1.0, 0.0, NULL, state, traction, tangent, &factor, message, sizeof message) != IWB_OK) {
      fprintf(stderr, "c_caller: increment %d: %s\n", k, message);
      return 1;
    }
    printf("%.17g,%.17g,%.17g\n", k * 0.05 / 100, traction[0], traction[1]);
  }
  iwb_material_destroy(m);
  return 0;
}
