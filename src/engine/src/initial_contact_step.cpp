#include "plyform/engine/initial_contact_step.hpp"

#include <exception>
#include <limits>

#include "mass.hpp"
#include "plyform/contact/contact_set.hpp"
#include "plyform/engine/initial_step.hpp"
#include "plyform/material/law_registry.hpp"
#include "plyform/rigid/rigid_bodies.hpp"

namespace plyform::engine {

std::vector<double> initial_contact_steps(const core::Model& model) {
  if (model.contacts.empty())
    return {};
  // The nodal masses and rotary inertias as Simulation::set_up_run lumps them (mass scaling
  // included), at the reference geometry.
  const ReferenceMasses ref = lumped_mass_at_reference(model);
  const std::vector<double>& mass = ref.mass;
  const std::vector<double>& inertia = ref.inertia;
  std::vector<unsigned char> rigid;
  try {
    rigid = rigid::RigidBodies(model).is_rigid_node();
  } catch (const std::exception&) {
    return {};  // the run stops at its set-up and says why
  }
  const std::size_t n = model.node_count();
  bool has_rigid = false;
  for (unsigned char r : rigid)
    has_rigid = has_rigid || r != 0;
  // The run's contact inertia: none at rigid nodes (their body takes forces only).
  std::vector<double> contact_inertia(n, 0.0), zero(n, 0.0), mx(n, 0.0), my(n, 0.0), mz(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    contact_inertia[i] = has_rigid && rigid[i] ? 0.0 : inertia[i];
  // The run's first element step with TSSFAC (SOFT = 1 reads it); without deformable
  // elements the run steps by DTINIT.
  const double tssfac = model.controls.tssfac > 0.0 ? model.controls.tssfac : 0.9;
  const InitialStep step = initial_stable_step(model);
  const double dt0 = step.dt < 1e300 ? tssfac * step.dt : model.controls.dt_init;
  // Positions x y z and velocities per node, as the run packs them at t = 0.
  std::vector<double> packed(6 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    packed[6 * i] = model.x0[i];
    packed[6 * i + 1] = model.y0[i];
    packed[6 * i + 2] = model.z0[i];
    if (!model.v0x.empty()) {
      packed[6 * i + 3] = model.v0x[i];
      packed[6 * i + 4] = model.v0y[i];
      packed[6 * i + 5] = model.v0z[i];
    }
  }
  // One interface at a time: a copy of the model that holds only that one (ContactSet votes
  // for all its interfaces together).
  std::vector<double> votes;
  votes.reserve(model.contacts.size());
  core::Model one = model;
  for (const core::ContactInterface& ci : model.contacts) {
    one.contacts.assign(1, ci);
    contact::ContactSet set(one, mass, has_rigid ? rigid.data() : nullptr, dt0, tssfac);
    set.follow_rotations({zero.data(), zero.data(), zero.data(), mx.data(), my.data(), mz.data(),
                          contact_inertia.data()});
    set.start(packed.data());
    votes.push_back(set.stable_step());
  }
  return votes;
}

}  // namespace plyform::engine
