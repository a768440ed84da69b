/* Compiled as C99: proves plyform_law.h is plain C, and drives one opening through it. */
#include <math.h>
#include <stddef.h>

#include "plyform/law/plyform_law.h"

/* Returns the pressure after opening a bonded node to `gap` in one step, or NaN on error. */
double c_header_open_once(double gap) {
  const double uc[] = {1.0, 30.0, 0.3, 0.3, 300.0, 500.0, 1e-6, 0.0, 0.0, 1.0, 1e-6};
  plyform_law* law = NULL;
  char message[256];
  if (plyform_law_create(uc, 11, NULL, 0, &law, message, sizeof message) != PLYFORM_LAW_OK) {
    return NAN;
  }
  plyform_law_history h;
  plyform_law_increment in = {0};
  plyform_law_response r;
  in.gap = gap;
  in.dt = 1e-3;
  in.temperature = 300.0;
  in.k_normal = 1000.0;
  in.area = 1.0;
  double result = NAN;
  if (plyform_law_initial_history(law, 0.0, &h) == PLYFORM_LAW_OK &&
      plyform_law_update_node(law, &in, &h, &r) == PLYFORM_LAW_OK) {
    result = r.pressure;
  }
  plyform_law_destroy(law);
  return result;
}
