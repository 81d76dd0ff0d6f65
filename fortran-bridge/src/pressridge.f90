!> pressridge: Fortran bindings of the pressridge C ABI (include/pressridge.h).
!>
!> Ice strength (Rothrock 1975 / Hibler 1979, as CICE/Icepack icepack_ice_strength), the
!> ridging step (as Icepack ridge_ice, and the complete icepack_step_ridge with snow, tracers
!> and fluxes), C_f and ridging lookup tables, and runs of the ridge simulator. Units are SI:
!> areas are fractions of the cell, volumes per unit area in m, thicknesses in m, rates in
!> 1/s, strength in N/m.
!>
!> Every routine takes an optional `ierr`. When `ierr` is present it receives the status
!> (PRESSRIDGE_OK = 0 or a PRESSRIDGE_ERR_* code) and the message is available from
!> pressridge_last_error_message(); when it is absent and an error occurs, the message is
!> printed on standard error and the program stops (error stop).
!>
!> Arrays are assumed-shape and contiguous (the compiler copies non-contiguous actual
!> arguments, e.g. CICE's aicen(i,j,:,iblk) in the per-cell call). Two layouts are accepted:
!> aicen(ncat, ncol) with per-column arrays x(ncol), and CICE's block layout aicen(nx, ny, ncat)
!> with per-column arrays x(nx, ny). Indices of tables (sets, variables) count from 1.
!> All routines are safe to call from several OpenMP threads at once; the last error is kept
!> per thread.
!>
!> This module owns no code: it is the public face, the list of every name a host gets with
!> `use pressridge`, taken from the modules that implement them (compile them in this order):
!>
!>   pressridge_cabi.f90       pressridge_cabi_mod       codes, bind(C) types, C interfaces
!>   pressridge_base.f90       pressridge_base_mod       errors, strings, options, layouts
!>   pressridge_strength.f90   pressridge_strength_mod   ice strength
!>   pressridge_ridging.f90    pressridge_ridging_mod    ridging step, complete step
!>   pressridge_simulator.f90  pressridge_simulator_mod  C_f and ridging tables, runs
!>   pressridge.f90            pressridge                this list
!>
!> See docs/fortran.md.
module pressridge
  use pressridge_cabi_mod, only: PRESSRIDGE_OK, PRESSRIDGE_ERR_NULL_POINTER, &
       PRESSRIDGE_ERR_BAD_SIZE, PRESSRIDGE_ERR_BAD_VALUE, PRESSRIDGE_ERR_NOT_FINITE, &
       PRESSRIDGE_ERR_IO, PRESSRIDGE_ERR_PARSE, PRESSRIDGE_ERR_BUFFER_TOO_SMALL, &
       PRESSRIDGE_ERR_NOT_FOUND, PRESSRIDGE_ERR_NUMERICAL, PRESSRIDGE_ERR_PANIC, &
       PRESSRIDGE_ABI_VERSION, &
       PRESSRIDGE_PARTICIPATION_THORNDIKE, PRESSRIDGE_PARTICIPATION_EXPONENTIAL, &
       PRESSRIDGE_REDISTRIBUTION_UNIFORM, PRESSRIDGE_REDISTRIBUTION_EXPONENTIAL, &
       PRESSRIDGE_REDISTRIBUTION_TABLE, pressridge_mu_rdg_table, &
       PRESSRIDGE_STRENGTH_HIBLER1979, PRESSRIDGE_STRENGTH_ROTHROCK, &
       PRESSRIDGE_CF_SOURCE_CONSTANT, PRESSRIDGE_CF_SOURCE_TABLE, &
       PRESSRIDGE_CF_HIBLER1980, PRESSRIDGE_CF_FLATO1991, PRESSRIDGE_CF_CICE, &
       PRESSRIDGE_TRACER_AGE, PRESSRIDGE_TRACER_FIRST_YEAR, PRESSRIDGE_TRACER_LEVEL_ICE, &
       PRESSRIDGE_TRACER_PONDS, PRESSRIDGE_TRACER_SNOW, PRESSRIDGE_TRACER_POND_TOPO, &
       PRESSRIDGE_TRACER_POND_SEALVL, PRESSRIDGE_TRACER_BRINE, PRESSRIDGE_BGC_NONE, &
       PRESSRIDGE_BGC_SKELETAL, PRESSRIDGE_BGC_VERTICAL, &
       pressridge_params, pressridge_options, pressridge_cf_table, pressridge_ridge_table, &
       pressridge_run, pressridge_ridger, pressridge_step_params
  use pressridge_base_mod, only: pressridge_last_error_message, pressridge_last_error_column, &
       pressridge_version, pressridge_linked_abi_version, &
       pressridge_default_options, pressridge_options_set_cf_table, &
       pressridge_options_set_mu_rdg_table, &
       pressridge_default_step_params, pressridge_init_parameters, pressridge_get_parameters
  use pressridge_strength_mod, only: pressridge_strength, pressridge_ice_strength
  use pressridge_ridging_mod, only: pressridge_ridge_step, pressridge_ridge_ice, &
       pressridge_ridger_init, pressridge_ridger_free, pressridge_step_ridge, &
       pressridge_step_ridge_cells
  use pressridge_simulator_mod, only: &
       pressridge_cf_table_open, pressridge_cf_table_open_at_friction, &
       pressridge_cf_table_new, pressridge_cf_table_lookup, pressridge_cf_table_nodes, &
       pressridge_cf_table_friction, pressridge_cf_table_free, &
       pressridge_mu_rdg_table_open, pressridge_mu_rdg_table_new, &
       pressridge_mu_rdg_table_lookup, pressridge_mu_rdg_table_free, &
       pressridge_ridge_table_open, pressridge_ridge_table_dims, pressridge_ridge_table_axes, &
       pressridge_ridge_table_set_name, pressridge_ridge_table_variable_name, &
       pressridge_ridge_table_value, pressridge_ridge_table_cf, &
       pressridge_ridge_table_cf_table, pressridge_ridge_table_friction_set, &
       pressridge_ridge_table_free, &
       pressridge_scene_run, pressridge_run_summary_json, pressridge_run_summary_value, &
       pressridge_run_free, pressridge_run_scene
  implicit none
  public
end module pressridge
