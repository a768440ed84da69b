/* C interface of the plyform interlayer contact law (docs/contact-law.md,
 * docs/host-integration.md).
 *
 * Plain C99: no exceptions cross it; every call returns a plyform_law_status. Usable from C,
 * C++, and from Fortran through the module plyform_law (iso_c_binding). A host creates one
 * plyform_law per interface from the *USER_INTERFACE_FRICTION constants, keeps one
 * plyform_law_history per slave node, and calls plyform_law_update_node (or the batched form)
 * every cycle.  Units: consistent units, as in LS-DYNA. */
#ifndef PLYFORM_LAW_H
#define PLYFORM_LAW_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum plyform_law_status {
  PLYFORM_LAW_OK = 0,
  PLYFORM_LAW_INVALID_ARGUMENT = 1,  /* a null pointer, a negative count, dt <= 0 ... */
  PLYFORM_LAW_INVALID_PARAMETER = 2, /* a constant out of range: see the message buffer */
  PLYFORM_LAW_OUT_OF_MEMORY = 3,
  PLYFORM_LAW_INTERNAL_ERROR = 4
} plyform_law_status;

/* Node states (the value of plyform_law_history.state). */
enum {
  PLYFORM_LAW_APPROACHING = 0,
  PLYFORM_LAW_CONTACT = 1,
  PLYFORM_LAW_SEPARATING = 2,
  PLYFORM_LAW_DETACHED = 3
};

/* Number of user constants UC1..UCn the law knows. */
#define PLYFORM_LAW_MAX_CONSTANTS 24

typedef struct plyform_law plyform_law; /* opaque, immutable once created: share across threads */

/* A load curve for -N slots: value against temperature, x strictly increasing. */
typedef struct plyform_law_curve {
  int32_t id;
  int32_t n_points;
  const double* x;
  const double* y;
} plyform_law_curve;

/* History of one slave node; zero it or fill it with plyform_law_initial_history. */
typedef struct plyform_law_history {
  int32_t state;
  int32_t reserved; /* padding, keep 0 */
  double beta;
  double gap;
  double slip[2];
  double opening[2];
  double e_damage, e_viscous, e_friction, e_damping, e_healing;
  double damping; /* the last normal damping traction (VDC): its work is booked with the next */
} plyform_law_history;

typedef struct plyform_law_increment {
  double gap;         /* surface gap at t_{n+1}, < 0 penetration */
  double slip[2];     /* tangential slip increment of slave relative to master, master plane */
  double dt;          /* > 0 */
  double temperature; /* slave node temperature */
  double k_normal;    /* penalty stiffness per area */
  double k_tangent;   /* stick stiffness per area */
  double area;        /* tributary area of the node (energies are booked times this) */
  double mass;        /* effective mass for normal damping, 0 = none */
} plyform_law_increment;

typedef struct plyform_law_response {
  double pressure; /* positive in compression */
  double tau[2];
  double stored;
} plyform_law_response;

/* Creates a law from UC1..UCn (n <= PLYFORM_LAW_MAX_CONSTANTS; NaN = blank, the default
 * applies) and the load curves its -N slots may reference. On PLYFORM_LAW_INVALID_PARAMETER,
 * every error is written to `message` (may be NULL), one per line, truncated to
 * `message_size` with a terminating NUL. */
plyform_law_status plyform_law_create(const double* constants, int32_t n_constants,
                                      const plyform_law_curve* curves, int32_t n_curves,
                                      plyform_law** law, char* message, size_t message_size);
void plyform_law_destroy(plyform_law* law);

/* History at t = 0 for a node at `gap` (bonded within BOND_TOL). */
plyform_law_status plyform_law_initial_history(const plyform_law* law, double gap,
                                               plyform_law_history* history);

/* One node, one cycle. */
plyform_law_status plyform_law_update_node(const plyform_law* law,
                                           const plyform_law_increment* increment,
                                           plyform_law_history* history,
                                           plyform_law_response* response);

/* Many nodes, one cycle, over host-owned arrays of length n (structure of arrays). `mass` and
 * `stored` may be NULL. `state` ... `e_healing` and `damping` are the history, updated in
 * place. */
typedef struct plyform_law_batch {
  int64_t n;
  double dt;
  const double *gap, *slip_x, *slip_y, *temperature, *k_normal, *k_tangent, *area, *mass;
  int32_t* state;
  double *beta, *hist_gap, *hist_slip_x, *hist_slip_y, *opening_x, *opening_y;
  double *e_damage, *e_viscous, *e_friction, *e_damping, *e_healing;
  double *pressure, *tau_x, *tau_y, *stored;
  double* damping; /* history: the last normal damping traction (plyform_law_history) */
} plyform_law_batch;

plyform_law_status plyform_law_update_batch(const plyform_law* law, const plyform_law_batch* batch);

/* Mode-I update with a three-value history, for hosts that allow no more (LS-DYNA's user
 * tiebreak utb101..105 keeps 3 history variables): hist[0] = state, hist[1] = beta,
 * hist[2] = gap. No tangential law, no energies. Initialise hist with
 * plyform_law_initial_history's state, beta and gap. */
plyform_law_status plyform_law_update_mode1(const plyform_law* law, double gap, double dt,
                                            double temperature, double k_normal, double hist[3],
                                            double* pressure);

/* Name of a state ("APPROACHING", ...), or "UNKNOWN". */
const char* plyform_law_state_name(int32_t state);

#ifdef __cplusplus
}
#endif

#endif /* PLYFORM_LAW_H */
