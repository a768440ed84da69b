#include "keyword_registry.hpp"

#include <algorithm>
#include <array>

namespace plyform::keyword {

// Each keyword lives in keywords/<name>.cpp with its card table and handler; adding one is
// one declaration and one table line here.
KeywordSpec keyword_keyword();
KeywordSpec title_keyword();
KeywordSpec end_keyword();
KeywordSpec comment_keyword();
KeywordSpec include_keyword();
KeywordSpec include_path_keyword();
KeywordSpec parameter_keyword();
KeywordSpec define_curve_keyword();
KeywordSpec define_coordinate_system_keyword();
KeywordSpec define_coordinate_vector_keyword();
KeywordSpec define_table_keyword();
KeywordSpec user_interface_friction_keyword();
KeywordSpec node_keyword();
KeywordSpec element_solid_keyword();
KeywordSpec element_shell_keyword();
KeywordSpec part_keyword();
KeywordSpec section_solid_keyword();
KeywordSpec section_shell_keyword();
KeywordSpec mat_elastic_keyword();
KeywordSpec mat_001_keyword();
KeywordSpec mat_orthotropic_elastic_keyword();
KeywordSpec mat_002_keyword();
KeywordSpec mat_reinforced_thermoplastic_keyword();
KeywordSpec mat_249_keyword();
KeywordSpec mat_elastic_plastic_thermal_keyword();
KeywordSpec mat_004_keyword();
KeywordSpec mat_power_law_plasticity_keyword();
KeywordSpec mat_018_keyword();
KeywordSpec mat_rigid_keyword();
KeywordSpec mat_020_keyword();
KeywordSpec mat_piecewise_linear_plasticity_keyword();
KeywordSpec mat_024_keyword();
KeywordSpec mat_plastic_kinematic_keyword();
KeywordSpec mat_003_keyword();
KeywordSpec mat_transversely_anisotropic_keyword();
KeywordSpec mat_037_keyword();
KeywordSpec mat_3_parameter_barlat_keyword();
KeywordSpec mat_036_keyword();
KeywordSpec mat_hill_3r_keyword();
KeywordSpec mat_122_keyword();
KeywordSpec mat_mooney_rivlin_keyword();
KeywordSpec mat_027_keyword();
KeywordSpec mat_add_thermal_expansion_keyword();
KeywordSpec mat_thermal_isotropic_keyword();
KeywordSpec mat_thermal_orthotropic_keyword();
KeywordSpec hourglass_keyword();
KeywordSpec set_node_list_keyword();
KeywordSpec set_part_list_keyword();
KeywordSpec set_node_keyword();
KeywordSpec set_part_keyword();
KeywordSpec set_segment_keyword();
KeywordSpec set_node_generate_keyword();
KeywordSpec set_node_list_generate_keyword();
KeywordSpec set_part_generate_keyword();
KeywordSpec set_part_list_generate_keyword();
KeywordSpec set_shell_list_keyword();
KeywordSpec set_shell_keyword();
KeywordSpec set_shell_generate_keyword();
KeywordSpec set_shell_list_generate_keyword();
KeywordSpec contact_one_way_surface_to_surface_keyword();
KeywordSpec contact_surface_to_surface_keyword();
KeywordSpec contact_forming_one_way_surface_to_surface_keyword();
KeywordSpec contact_automatic_surface_to_surface_keyword();
KeywordSpec contact_automatic_one_way_surface_to_surface_keyword();
KeywordSpec contact_automatic_single_surface_keyword();
KeywordSpec contact_tied_nodes_to_surface_keyword();
KeywordSpec contact_tied_shell_edge_to_surface_keyword();
KeywordSpec boundary_spc_node_keyword();
KeywordSpec boundary_spc_set_keyword();
KeywordSpec boundary_prescribed_motion_node_keyword();
KeywordSpec boundary_prescribed_motion_set_keyword();
KeywordSpec boundary_prescribed_motion_rigid_keyword();
KeywordSpec boundary_temperature_node_keyword();
KeywordSpec boundary_temperature_set_keyword();
KeywordSpec boundary_convection_set_keyword();
KeywordSpec boundary_flux_set_keyword();
KeywordSpec boundary_radiation_set_keyword();
KeywordSpec initial_velocity_generation_keyword();
KeywordSpec initial_velocity_node_keyword();
KeywordSpec initial_stress_shell_keyword();
KeywordSpec initial_strain_shell_keyword();
KeywordSpec initial_temperature_node_keyword();
KeywordSpec initial_temperature_set_keyword();
KeywordSpec load_node_point_keyword();
KeywordSpec load_node_set_keyword();
KeywordSpec load_rigid_body_keyword();
KeywordSpec load_segment_keyword();
KeywordSpec load_segment_set_keyword();
KeywordSpec load_shell_element_keyword();
KeywordSpec load_shell_set_keyword();
KeywordSpec rigidwall_planar_keyword();
KeywordSpec control_termination_keyword();
KeywordSpec control_timestep_keyword();
KeywordSpec control_energy_keyword();
KeywordSpec control_hourglass_keyword();
KeywordSpec control_shell_keyword();
KeywordSpec control_contact_keyword();
KeywordSpec control_units_keyword();
KeywordSpec control_solution_keyword();
KeywordSpec control_thermal_solver_keyword();
KeywordSpec control_thermal_timestep_keyword();
KeywordSpec database_binary_d3plot_keyword();
KeywordSpec database_binary_d3dump_keyword();
KeywordSpec database_glstat_keyword();
KeywordSpec database_nodout_keyword();
KeywordSpec database_rcforc_keyword();
KeywordSpec database_bndout_keyword();
KeywordSpec database_spcforc_keyword();
KeywordSpec control_accuracy_keyword();
KeywordSpec control_bulk_viscosity_keyword();
KeywordSpec control_adaptive_keyword();
KeywordSpec control_adapstep_keyword();
KeywordSpec control_solid_keyword();
KeywordSpec control_parallel_keyword();
KeywordSpec interface_springback_lsdyna_keyword();
KeywordSpec control_output_keyword();
KeywordSpec control_rigid_keyword();
KeywordSpec database_sleout_keyword();
KeywordSpec database_rwforc_keyword();
KeywordSpec database_matsum_keyword();
KeywordSpec database_tprint_keyword();
KeywordSpec database_history_node_keyword();
KeywordSpec database_elout_keyword();
KeywordSpec database_extent_binary_keyword();
KeywordSpec database_history_shell_keyword();
KeywordSpec database_history_solid_keyword();

std::span<const KeywordSpec> keyword_registry() {
  static const std::array kRegistry{
      keyword_keyword(),
      title_keyword(),
      end_keyword(),
      comment_keyword(),
      include_keyword(),
      include_path_keyword(),
      parameter_keyword(),
      define_curve_keyword(),
      define_coordinate_system_keyword(),
      define_coordinate_vector_keyword(),
      define_table_keyword(),
      user_interface_friction_keyword(),
      node_keyword(),
      element_solid_keyword(),
      element_shell_keyword(),
      part_keyword(),
      section_solid_keyword(),
      section_shell_keyword(),
      mat_elastic_keyword(),
      mat_001_keyword(),
      mat_orthotropic_elastic_keyword(),
      mat_002_keyword(),
      mat_reinforced_thermoplastic_keyword(),
      mat_249_keyword(),
      mat_elastic_plastic_thermal_keyword(),
      mat_004_keyword(),
      mat_power_law_plasticity_keyword(),
      mat_018_keyword(),
      mat_rigid_keyword(),
      mat_020_keyword(),
      mat_piecewise_linear_plasticity_keyword(),
      mat_024_keyword(),
      mat_plastic_kinematic_keyword(),
      mat_003_keyword(),
      mat_transversely_anisotropic_keyword(),
      mat_037_keyword(),
      mat_3_parameter_barlat_keyword(),
      mat_036_keyword(),
      mat_hill_3r_keyword(),
      mat_122_keyword(),
      mat_mooney_rivlin_keyword(),
      mat_027_keyword(),
      mat_add_thermal_expansion_keyword(),
      mat_thermal_isotropic_keyword(),
      mat_thermal_orthotropic_keyword(),
      hourglass_keyword(),
      set_node_list_keyword(),
      set_part_list_keyword(),
      set_node_keyword(),
      set_part_keyword(),
      set_segment_keyword(),
      set_node_generate_keyword(),
      set_node_list_generate_keyword(),
      set_part_generate_keyword(),
      set_part_list_generate_keyword(),
      set_shell_list_keyword(),
      set_shell_keyword(),
      set_shell_generate_keyword(),
      set_shell_list_generate_keyword(),
      contact_one_way_surface_to_surface_keyword(),
      contact_surface_to_surface_keyword(),
      contact_forming_one_way_surface_to_surface_keyword(),
      contact_automatic_surface_to_surface_keyword(),
      contact_automatic_one_way_surface_to_surface_keyword(),
      contact_automatic_single_surface_keyword(),
      contact_tied_nodes_to_surface_keyword(),
      contact_tied_shell_edge_to_surface_keyword(),
      boundary_spc_node_keyword(),
      boundary_spc_set_keyword(),
      boundary_prescribed_motion_node_keyword(),
      boundary_prescribed_motion_set_keyword(),
      boundary_prescribed_motion_rigid_keyword(),
      boundary_temperature_node_keyword(),
      boundary_temperature_set_keyword(),
      boundary_convection_set_keyword(),
      boundary_flux_set_keyword(),
      boundary_radiation_set_keyword(),
      initial_velocity_generation_keyword(),
      initial_velocity_node_keyword(),
      initial_stress_shell_keyword(),
      initial_strain_shell_keyword(),
      initial_temperature_node_keyword(),
      initial_temperature_set_keyword(),
      load_node_point_keyword(),
      load_node_set_keyword(),
      load_rigid_body_keyword(),
      load_segment_keyword(),
      load_segment_set_keyword(),
      load_shell_element_keyword(),
      load_shell_set_keyword(),
      rigidwall_planar_keyword(),
      control_termination_keyword(),
      control_timestep_keyword(),
      control_energy_keyword(),
      control_accuracy_keyword(),
      control_bulk_viscosity_keyword(),
      control_adaptive_keyword(),
      control_adapstep_keyword(),
      control_solid_keyword(),
      control_parallel_keyword(),
      interface_springback_lsdyna_keyword(),
      control_output_keyword(),
      control_rigid_keyword(),
      control_hourglass_keyword(),
      control_shell_keyword(),
      control_contact_keyword(),
      control_units_keyword(),
      control_solution_keyword(),
      control_thermal_solver_keyword(),
      control_thermal_timestep_keyword(),
      database_binary_d3plot_keyword(),
      database_binary_d3dump_keyword(),
      database_glstat_keyword(),
      database_nodout_keyword(),
      database_rcforc_keyword(),
      database_bndout_keyword(),
      database_spcforc_keyword(),
      database_sleout_keyword(),
      database_rwforc_keyword(),
      database_matsum_keyword(),
      database_tprint_keyword(),
      database_history_node_keyword(),
      database_elout_keyword(),
      database_extent_binary_keyword(),
      database_history_shell_keyword(),
      database_history_solid_keyword(),
  };
  return kRegistry;
}

namespace {

const KeywordSpec* find_exact(std::string_view name) {
  const auto registry = keyword_registry();
  const auto it = std::find_if(registry.begin(), registry.end(),
                               [&](const KeywordSpec& spec) { return spec.name == name; });
  return it == registry.end() ? nullptr : &*it;
}

bool supports(const KeywordSpec& spec, std::string_view option) {
  return std::find(spec.options.begin(), spec.options.end(), option) != spec.options.end();
}

}  // namespace

KeywordLookup find_keyword(std::string_view name) {
  KeywordLookup longest;
  if (const KeywordSpec* spec = find_exact(name)) {
    if (supports(*spec, "")) {
      return {spec, "", true};
    }
    longest = {spec, "", false};
  }
  for (std::size_t cut = name.rfind('_'); cut != std::string_view::npos && cut > 0;
       cut = name.rfind('_', cut - 1)) {
    const KeywordSpec* spec = find_exact(name.substr(0, cut));
    if (spec == nullptr) {
      continue;
    }
    const std::string_view option = name.substr(cut + 1);
    if (supports(*spec, option)) {
      return {spec, std::string(option), true};
    }
    if (longest.spec == nullptr) {
      longest = {spec, std::string(option), false};
    }
  }
  return longest;
}

}  // namespace plyform::keyword
