#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "plyform/model/boundary_desc.hpp"
#include "plyform/model/contact_desc.hpp"
#include "plyform/model/control_desc.hpp"
#include "plyform/model/coordinate_system_desc.hpp"
#include "plyform/model/curve_desc.hpp"
#include "plyform/model/database_desc.hpp"
#include "plyform/model/define_table_desc.hpp"
#include "plyform/model/element_shell_desc.hpp"
#include "plyform/model/element_solid_desc.hpp"
#include "plyform/model/hourglass_desc.hpp"
#include "plyform/model/initial_shell_state_desc.hpp"
#include "plyform/model/initial_velocity_desc.hpp"
#include "plyform/model/load_node_desc.hpp"
#include "plyform/model/load_pressure_desc.hpp"
#include "plyform/model/load_rigid_body_desc.hpp"
#include "plyform/model/mat_elastic_desc.hpp"
#include "plyform/model/mat_mooney_rivlin_desc.hpp"
#include "plyform/model/mat_orthotropic_elastic_desc.hpp"
#include "plyform/model/mat_plasticity_desc.hpp"
#include "plyform/model/mat_reinforced_thermoplastic_desc.hpp"
#include "plyform/model/mat_rigid_desc.hpp"
#include "plyform/model/mat_sheet_metal_desc.hpp"
#include "plyform/model/mat_thermal_plasticity_desc.hpp"
#include "plyform/model/node_desc.hpp"
#include "plyform/model/part_desc.hpp"
#include "plyform/model/rigid_wall_desc.hpp"
#include "plyform/model/section_shell_desc.hpp"
#include "plyform/model/section_solid_desc.hpp"
#include "plyform/model/set_desc.hpp"
#include "plyform/model/temperature_desc.hpp"
#include "plyform/model/thermal_desc.hpp"
#include "plyform/model/user_interface_friction_desc.hpp"

namespace plyform::model {

/// The whole deck as plain data keyed by deck ids, in the order the keywords were read.
/// Each supported keyword adds one vector of its *Desc struct here; a *CONTROL_ or
/// *DATABASE_ keyword that LS-DYNA reads once is an optional (the last one read wins, with a
/// warning).
struct ModelDesc {
  std::string title;            ///< *TITLE (the last one read)
  std::string keyword_options;  ///< text after *KEYWORD on its line (memory size, ...), if any
  std::vector<CurveDesc> curves;
  std::vector<DefineTableDesc> tables;  ///< *DEFINE_TABLE; their curves are in `curves`
  std::vector<UserInterfaceFrictionDesc> user_interface_frictions;

  // Mesh
  std::vector<NodeDesc> nodes;
  std::vector<ElementSolidDesc> solids;
  std::vector<ElementShellDesc> shells;
  std::vector<PartDesc> parts;
  std::vector<SectionSolidDesc> solid_sections;
  std::vector<SectionShellDesc> shell_sections;
  std::vector<MatElasticDesc> elastic_materials;
  std::vector<MatOrthotropicElasticDesc> orthotropic_elastic_materials;
  std::vector<MatPowerLawPlasticityDesc> power_law_materials;
  std::vector<MatRigidDesc> rigid_materials;
  std::vector<MatPiecewiseLinearPlasticityDesc> piecewise_linear_materials;
  std::vector<MatMooneyRivlinDesc> mooney_rivlin_materials;
  std::vector<MatElasticPlasticThermalDesc> elastic_plastic_thermal_materials;
  std::vector<MatReinforcedThermoplasticDesc> reinforced_thermoplastic_materials;
  std::vector<MatPlasticKinematicDesc> plastic_kinematic_materials;
  std::vector<MatTransverselyAnisotropicDesc> transversely_anisotropic_materials;
  std::vector<MatBarlat89Desc> barlat89_materials;
  std::vector<MatHill3RDesc> hill_3r_materials;
  std::vector<MatAddThermalExpansionDesc> thermal_expansions;
  std::vector<HourglassDesc> hourglasses;
  std::vector<SetListDesc> node_sets;
  std::vector<SetListDesc> part_sets;
  std::vector<SetSegmentDesc> segment_sets;
  std::vector<SetListDesc> shell_sets;  ///< *SET_SHELL(_LIST): shell element ids
  /// *DEFINE_COORDINATE_SYSTEM and *DEFINE_COORDINATE_VECTOR (one id range).
  std::vector<CoordinateSystemDesc> coordinate_systems;

  // Contact
  std::vector<ContactDesc> contacts;
  std::optional<ControlContactDesc> control_contact;

  // Loads, constraints, initial conditions
  std::vector<BoundarySpcDesc> spcs;
  std::vector<PrescribedMotionDesc> prescribed_motions;
  std::vector<PrescribedMotionRigidDesc> rigid_motions;
  std::vector<LoadNodeDesc> nodal_loads;
  std::vector<LoadPressureDesc> pressure_loads;  ///< *LOAD_SEGMENT(_SET), *LOAD_SHELL_*
  std::vector<LoadRigidBodyDesc> rigid_body_loads;
  std::vector<RigidWallDesc> rigid_walls;  ///< *RIGIDWALL_PLANAR(_FINITE, _MOVING, _FORCES)
  std::vector<InitialVelocityGenerationDesc> initial_velocities;
  std::vector<InitialVelocityNodeDesc> initial_node_velocities;
  std::vector<InitialTemperatureDesc> initial_temperatures;
  std::vector<BoundaryTemperatureDesc> temperature_histories;
  std::vector<InitialStressShellDesc> initial_shell_stresses;  ///< *INITIAL_STRESS_SHELL
  std::vector<InitialStrainShellDesc> initial_shell_strains;   ///< *INITIAL_STRAIN_SHELL

  // Heat transfer (computed temperatures)
  std::optional<ControlSolutionDesc> control_solution;
  std::optional<ControlThermalSolverDesc> thermal_solver;
  std::optional<ControlThermalTimestepDesc> thermal_timestep;
  std::vector<MatThermalDesc> thermal_materials;
  std::vector<HeatBoundaryDesc> heat_boundaries;
  std::optional<DatabaseTprintDesc> tprint;

  // Control and output
  std::optional<ControlTerminationDesc> termination;
  std::optional<ControlTimestepDesc> timestep;
  std::optional<ControlEnergyDesc> energy;
  std::optional<ControlHourglassDesc> control_hourglass;
  std::optional<ControlShellDesc> control_shell;
  std::optional<ControlUnitsDesc> units;
  std::optional<ControlAccuracyDesc> accuracy;
  std::optional<ControlBulkViscosityDesc> bulk_viscosity;
  std::optional<ControlParallelDesc> parallel;  ///< *CONTROL_PARALLEL: `plyform run`'s threads
  std::optional<DatabaseBinaryD3plotDesc> d3plot;
  std::optional<DatabaseBinaryD3dumpDesc> d3dump;
  std::vector<DatabaseAsciiDesc> ascii_outputs;  ///< *DATABASE_GLSTAT, _NODOUT, _RCFORC
  std::vector<DatabaseHistoryNodeDesc> history_nodes;
  std::optional<DatabaseEloutDesc> elout;
  std::optional<DatabaseExtentBinaryDesc> extent_binary;
  std::vector<DatabaseHistoryElementDesc> history_elements;  ///< _SHELL and _SOLID, deck order
  std::optional<InterfaceSpringbackDesc> springback;  ///< *INTERFACE_SPRINGBACK_LSDYNA (dynain)

  std::vector<std::string> files_read;  ///< the main deck first, then each include as opened
  /// FNV-1a (64 bit) over the text of every file read, in reading order: a checkpoint belongs
  /// to the deck whose files give the same value.
  std::uint64_t source_fingerprint = 14695981039346656037ull;
};

/// The curve ids of a table: the ids of the curves read after it, one per value (fewer when the
/// deck ends first).
inline std::vector<int> table_curve_ids(const ModelDesc& deck, const DefineTableDesc& table) {
  std::vector<int> ids;
  for (std::size_t i = table.first_curve;
       i < deck.curves.size() && ids.size() < table.values.size(); ++i)
    ids.push_back(deck.curves[i].id);
  return ids;
}

}  // namespace plyform::model
