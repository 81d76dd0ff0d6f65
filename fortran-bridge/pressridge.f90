!> pressridge: Fortran bindings of the pressridge C ABI (include/pressridge.h).
!>
!> Ice strength (Rothrock 1975 / Hibler 1979, as CICE/Icepack icepack_ice_strength), the
!> ridging step (as Icepack ridge_ice, without snow and tracers), C_f and ridging lookup
!> tables, and runs of the ridge simulator. Units are SI: areas are fractions of the cell,
!> volumes per unit area in m, thicknesses in m, rates in 1/s, strength in N/m.
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
!> See docs/fortran.md.
module pressridge
  use, intrinsic :: iso_c_binding
  use, intrinsic :: iso_fortran_env, only: error_unit
  implicit none
  private

  ! Status codes (docs/c-api.md).
  integer, parameter, public :: PRESSRIDGE_OK = 0
  integer, parameter, public :: PRESSRIDGE_ERR_NULL_POINTER = 1
  integer, parameter, public :: PRESSRIDGE_ERR_BAD_SIZE = 2
  integer, parameter, public :: PRESSRIDGE_ERR_BAD_VALUE = 3
  integer, parameter, public :: PRESSRIDGE_ERR_NOT_FINITE = 4
  integer, parameter, public :: PRESSRIDGE_ERR_IO = 5
  integer, parameter, public :: PRESSRIDGE_ERR_PARSE = 6
  integer, parameter, public :: PRESSRIDGE_ERR_BUFFER_TOO_SMALL = 7
  integer, parameter, public :: PRESSRIDGE_ERR_NOT_FOUND = 8
  integer, parameter, public :: PRESSRIDGE_ERR_NUMERICAL = 9
  integer, parameter, public :: PRESSRIDGE_ERR_PANIC = 10
  !> C ABI version these bindings were written for.
  integer, parameter, public :: PRESSRIDGE_ABI_VERSION = 1

  ! Option codes: the values of CICE's krdg_partic, krdg_redist and kstrength.
  integer(c_int32_t), parameter, public :: PRESSRIDGE_PARTICIPATION_THORNDIKE = 0
  integer(c_int32_t), parameter, public :: PRESSRIDGE_PARTICIPATION_EXPONENTIAL = 1
  integer(c_int32_t), parameter, public :: PRESSRIDGE_REDISTRIBUTION_UNIFORM = 0
  integer(c_int32_t), parameter, public :: PRESSRIDGE_REDISTRIBUTION_EXPONENTIAL = 1
  integer(c_int32_t), parameter, public :: PRESSRIDGE_STRENGTH_HIBLER1979 = 0
  integer(c_int32_t), parameter, public :: PRESSRIDGE_STRENGTH_ROTHROCK = 1
  integer(c_int32_t), parameter, public :: PRESSRIDGE_CF_SOURCE_CONSTANT = 0
  integer(c_int32_t), parameter, public :: PRESSRIDGE_CF_SOURCE_TABLE = 1
  !> C_f presets (dimensionless): Hibler (1980), Flato (1991), CICE/Icepack.
  real(c_double), parameter, public :: PRESSRIDGE_CF_HIBLER1980 = 2.0_c_double
  real(c_double), parameter, public :: PRESSRIDGE_CF_FLATO1991 = 15.0_c_double
  real(c_double), parameter, public :: PRESSRIDGE_CF_CICE = 17.0_c_double

  ! Tracer flags of the complete ridging step (Icepack tr_iage, tr_FY, tr_lvl, tr_pond_lvl).
  integer(c_int32_t), parameter, public :: PRESSRIDGE_TRACER_AGE = 1
  integer(c_int32_t), parameter, public :: PRESSRIDGE_TRACER_FIRST_YEAR = 2
  integer(c_int32_t), parameter, public :: PRESSRIDGE_TRACER_LEVEL_ICE = 4
  integer(c_int32_t), parameter, public :: PRESSRIDGE_TRACER_PONDS = 8

  !> Physical constants and tunables (C struct PressridgeParams). The initial values are
  !> CICE's defaults, the same as pressridge_default_options returns (checked by the tests).
  type, bind(C), public :: pressridge_params
     real(c_double) :: rhoi = 917.0_c_double          !< sea ice density (kg/m3)
     real(c_double) :: rhow = 1026.0_c_double         !< sea water density (kg/m3)
     real(c_double) :: gravit = 9.80616_c_double      !< gravitational acceleration (m/s2)
     real(c_double) :: gstar = 0.15_c_double          !< participation cut-off G* (1)
     real(c_double) :: astar = 0.05_c_double          !< exponential participation a* (1)
     real(c_double) :: hstar = 25.0_c_double          !< uniform redistribution H* (m)
     real(c_double) :: maxraft = 1.0_c_double         !< largest rafting thickness (m)
     real(c_double) :: mu_rdg = 3.0_c_double          !< exponential redistribution mu (m^0.5)
     real(c_double) :: cs = 0.25_c_double             !< shear fraction C_s (1)
     real(c_double) :: pstar = 2.75e4_c_double        !< Hibler P* (N/m2)
     real(c_double) :: cstar = 20.0_c_double          !< Hibler C* (1)
     real(c_double) :: puny = 1.0e-11_c_double        !< smallest non-zero area (1)
     real(c_double) :: exp_argmax = 100.0_c_double    !< largest exponential argument (1)
     real(c_double) :: big = 1.0e8_c_double           !< upper bound of the last category (m)
     real(c_double) :: area_tolerance = 1.0e-6_c_double !< |aice0 + sum(aicen) - 1| accepted (1)
     real(c_double) :: max_area_before_ridging = 2.0_c_double !< largest area before ridging (1)
     integer(c_int64_t) :: nitermax = 20              !< maximum ridging iterations
  end type pressridge_params

  !> Options of the strength and ridging calls (C struct PressridgeOptions); initial values
  !> are CICE's defaults. Set cf_table with pressridge_options_set_cf_table.
  type, bind(C), public :: pressridge_options
     integer(c_int32_t) :: participation = PRESSRIDGE_PARTICIPATION_EXPONENTIAL
     integer(c_int32_t) :: redistribution = PRESSRIDGE_REDISTRIBUTION_EXPONENTIAL
     integer(c_int32_t) :: strength_law = PRESSRIDGE_STRENGTH_ROTHROCK
     integer(c_int32_t) :: cf_source = PRESSRIDGE_CF_SOURCE_CONSTANT
     real(c_double) :: cf = PRESSRIDGE_CF_CICE        !< constant C_f (1)
     real(c_double) :: fill = 0.0_c_double            !< output of columns with valid = .false.
     type(c_ptr) :: cf_table = c_null_ptr             !< C_f table (PRESSRIDGE_CF_SOURCE_TABLE)
     type(pressridge_params) :: params
  end type pressridge_options

  !> A C_f table handle (free with pressridge_cf_table_free).
  type, public :: pressridge_cf_table
     type(c_ptr) :: ptr = c_null_ptr
  end type pressridge_cf_table

  !> A ridging lookup table handle (free with pressridge_ridge_table_free).
  type, public :: pressridge_ridge_table
     type(c_ptr) :: ptr = c_null_ptr
  end type pressridge_ridge_table

  !> A simulator run handle (free with pressridge_run_free).
  type, public :: pressridge_run
     type(c_ptr) :: ptr = c_null_ptr
  end type pressridge_run

  !> A ridging set-up for the complete step (free with pressridge_ridger_free): number of
  !> categories, tracer layout (Icepack's, passed once) and options.
  type, public :: pressridge_ridger
     type(c_ptr) :: ptr = c_null_ptr
     integer :: ncat = 0   !< thickness categories
     integer :: ntrcr = 0  !< tracers per category
  end type pressridge_ridger

  type, bind(C) :: c_fluxes
     real(c_double) :: fresh = 0, fsalt = 0, fhocn = 0, fpond = 0, dpnd_ridge = 0
  end type c_fluxes

  type, bind(C) :: c_step_diag
     real(c_double) :: closing = 0, opening = 0, dardg1dt = 0, dardg2dt = 0, dvirdgdt = 0, &
          ice_to_ocean = 0, snow_to_ocean = 0
     integer(c_int64_t) :: niter = 0
  end type c_step_diag

  type, bind(C) :: c_cat_diag
     type(c_ptr) :: dardg1ndt = c_null_ptr, dardg2ndt = c_null_ptr, dvirdgndt = c_null_ptr, &
          aparticn = c_null_ptr, krdgn = c_null_ptr, araftn = c_null_ptr, vraftn = c_null_ptr, &
          aredistn = c_null_ptr, vredistn = c_null_ptr, first_ice = c_null_ptr
  end type c_cat_diag

  type, bind(C) :: c_cell_arrays
     type(c_ptr) :: rdg_conv = c_null_ptr, rdg_shear = c_null_ptr, closing = c_null_ptr, &
          opening = c_null_ptr, tf = c_null_ptr, valid = c_null_ptr, fresh = c_null_ptr, &
          fsalt = c_null_ptr, fhocn = c_null_ptr, fpond = c_null_ptr, dardg1dt = c_null_ptr, &
          dardg2dt = c_null_ptr, dvirdgdt = c_null_ptr
  end type c_cell_arrays

  type, bind(C) :: c_grid
     integer(c_int64_t) :: ncat, ncol, cat_stride, col_stride, len, col_stride_1d, len_1d
  end type c_grid

  type, bind(C) :: c_rates
     type(c_ptr) :: closing = c_null_ptr, opening = c_null_ptr, dardg1dt = c_null_ptr, &
          dardg2dt = c_null_ptr, dvirdgdt = c_null_ptr
  end type c_rates

  !> Options used by pressridge_ice_strength and pressridge_ridge_ice (the Icepack-style
  !> calls); set with pressridge_init_parameters.
  type(pressridge_options), save, target :: icepack_options

  interface
     integer(c_int32_t) function c_last_error(buf, len, required) &
          bind(C, name="pressridge_last_error")
       import :: c_int32_t, c_int64_t, c_ptr
       type(c_ptr), value :: buf
       integer(c_int64_t), value :: len
       integer(c_int64_t), intent(out) :: required
     end function c_last_error
     integer(c_int32_t) function c_last_error_info(code, column) &
          bind(C, name="pressridge_last_error_info")
       import :: c_int32_t, c_int64_t
       integer(c_int32_t), intent(out) :: code
       integer(c_int64_t), intent(out) :: column
     end function c_last_error_info
     integer(c_int32_t) function c_set_error(code, message, len) &
          bind(C, name="pressridge_set_error")
       import :: c_int32_t, c_int64_t, c_char
       integer(c_int32_t), value :: code
       character(kind=c_char), intent(in) :: message(*)
       integer(c_int64_t), value :: len
     end function c_set_error
     integer(c_int32_t) function c_version(buf, len, required) bind(C, name="pressridge_version")
       import :: c_int32_t, c_int64_t, c_ptr
       type(c_ptr), value :: buf
       integer(c_int64_t), value :: len
       integer(c_int64_t), intent(out) :: required
     end function c_version
     integer(c_int32_t) function c_abi_version(v) bind(C, name="pressridge_abi_version")
       import :: c_int32_t
       integer(c_int32_t), intent(out) :: v
     end function c_abi_version
     integer(c_int32_t) function c_options_default(o) bind(C, name="pressridge_options_default")
       import :: c_int32_t, pressridge_options
       type(pressridge_options), intent(out) :: o
     end function c_options_default
     integer(c_int32_t) function c_strength(grid, aicen, vicen, aice0, valid, options, &
          strength, cf_clamped) bind(C, name="pressridge_strength")
       import :: c_int32_t, c_ptr, c_grid
       type(c_grid), intent(in) :: grid
       type(c_ptr), value :: aicen, vicen, aice0, valid, options, strength, cf_clamped
     end function c_strength
     integer(c_int32_t) function c_strength_cell(ncat, aicen, vicen, aice0, options, &
          strength) bind(C, name="pressridge_strength_cell")
       import :: c_int32_t, c_int64_t, c_ptr, c_double
       integer(c_int64_t), value :: ncat
       type(c_ptr), value :: aicen, vicen
       real(c_double), value :: aice0
       type(c_ptr), value :: options, strength
     end function c_strength_cell
     integer(c_int32_t) function c_ridge_step(grid, aicen, vicen, aice0, hin_max, nbounds, &
          convergence, shear, dt, valid, options, rates) bind(C, name="pressridge_ridge_step")
       import :: c_int32_t, c_int64_t, c_ptr, c_double, c_grid, c_rates
       type(c_grid), intent(in) :: grid
       type(c_ptr), value :: aicen, vicen, aice0, hin_max
       integer(c_int64_t), value :: nbounds
       type(c_ptr), value :: convergence, shear
       real(c_double), value :: dt
       type(c_ptr), value :: valid, options
       type(c_rates), intent(in) :: rates
     end function c_ridge_step
     integer(c_int32_t) function c_ridger_new(ncat, nilyr, nslyr, flags, options, step, &
          cleanup, rebin, ridger) bind(C, name="pressridge_ridger_new")
       import :: c_int32_t, c_int64_t, c_ptr
       integer(c_int64_t), value :: ncat, nilyr, nslyr
       integer(c_int32_t), value :: flags
       type(c_ptr), value :: options, step
       integer(c_int32_t), value :: cleanup, rebin
       type(c_ptr), intent(out) :: ridger
     end function c_ridger_new
     integer(c_int32_t) function c_ridger_free(ridger) bind(C, name="pressridge_ridger_free")
       import :: c_int32_t, c_ptr
       type(c_ptr), value :: ridger
     end function c_ridger_free
     integer(c_int32_t) function c_ridger_tracers(ridger, ntrcr, len, depend, base, nstrata, &
          strata) bind(C, name="pressridge_ridger_tracers")
       import :: c_int32_t, c_int64_t, c_ptr
       type(c_ptr), value :: ridger
       integer(c_int64_t), intent(out) :: ntrcr
       integer(c_int64_t), value :: len
       type(c_ptr), value :: depend, base, nstrata, strata
     end function c_ridger_tracers
     integer(c_int32_t) function c_ridge_cell(ridger, dt, ndtd, hin_max, rdg_conv, rdg_shear, &
          closing, opening, aicen, trcrn, vicen, vsnon, aice0, aice, tf, fluxes, diag, cats) &
          bind(C, name="pressridge_ridge_cell")
       import :: c_int32_t, c_ptr, c_double, c_fluxes, c_step_diag, c_cat_diag
       type(c_ptr), value :: ridger
       real(c_double), value :: dt
       integer(c_int32_t), value :: ndtd
       type(c_ptr), value :: hin_max
       real(c_double), value :: rdg_conv, rdg_shear
       type(c_ptr), value :: closing, opening, aicen, trcrn, vicen, vsnon, aice0, aice
       real(c_double), value :: tf
       type(c_fluxes), intent(inout) :: fluxes
       type(c_step_diag), intent(out) :: diag
       type(c_cat_diag), intent(in) :: cats
     end function c_ridge_cell
     integer(c_int32_t) function c_ridge_cells(ridger, ncol, dt, ndtd, hin_max, aicen, trcrn, &
          vicen, vsnon, aice0, aice, cells) bind(C, name="pressridge_ridge_cells")
       import :: c_int32_t, c_int64_t, c_ptr, c_double, c_cell_arrays
       type(c_ptr), value :: ridger
       integer(c_int64_t), value :: ncol
       real(c_double), value :: dt
       integer(c_int32_t), value :: ndtd
       type(c_ptr), value :: hin_max, aicen, trcrn, vicen, vsnon, aice0, aice
       type(c_cell_arrays), intent(in) :: cells
     end function c_ridge_cells
     integer(c_int32_t) function c_cf_table_open(path, len, table) &
          bind(C, name="pressridge_cf_table_open")
       import :: c_int32_t, c_int64_t, c_char, c_ptr
       character(kind=c_char), intent(in) :: path(*)
       integer(c_int64_t), value :: len
       type(c_ptr), intent(out) :: table
     end function c_cf_table_open
     integer(c_int32_t) function c_cf_table_open_at_friction(path, len, mu, mu_w, table) &
          bind(C, name="pressridge_cf_table_open_at_friction")
       import :: c_int32_t, c_int64_t, c_char, c_double, c_ptr
       character(kind=c_char), intent(in) :: path(*)
       integer(c_int64_t), value :: len
       real(c_double), value :: mu, mu_w
       type(c_ptr), intent(out) :: table
     end function c_cf_table_open_at_friction
     integer(c_int32_t) function c_cf_table_friction(table, mu, mu_w, known) &
          bind(C, name="pressridge_cf_table_friction")
       import :: c_int32_t, c_double, c_ptr
       type(c_ptr), value :: table
       real(c_double), intent(out) :: mu, mu_w
       integer(c_int32_t), intent(out) :: known
     end function c_cf_table_friction
     integer(c_int32_t) function c_cf_table_new(thickness, cf, n, table) &
          bind(C, name="pressridge_cf_table_new")
       import :: c_int32_t, c_int64_t, c_double, c_ptr
       real(c_double), intent(in) :: thickness(*), cf(*)
       integer(c_int64_t), value :: n
       type(c_ptr), intent(out) :: table
     end function c_cf_table_new
     integer(c_int32_t) function c_cf_table_len(table, n) bind(C, name="pressridge_cf_table_len")
       import :: c_int32_t, c_int64_t, c_ptr
       type(c_ptr), value :: table
       integer(c_int64_t), intent(out) :: n
     end function c_cf_table_len
     integer(c_int32_t) function c_cf_table_nodes(table, thickness, cf, len) &
          bind(C, name="pressridge_cf_table_nodes")
       import :: c_int32_t, c_int64_t, c_double, c_ptr
       type(c_ptr), value :: table
       real(c_double), intent(out) :: thickness(*), cf(*)
       integer(c_int64_t), value :: len
     end function c_cf_table_nodes
     integer(c_int32_t) function c_cf_table_lookup(table, h, cf, clamped) &
          bind(C, name="pressridge_cf_table_lookup")
       import :: c_int32_t, c_double, c_ptr
       type(c_ptr), value :: table
       real(c_double), value :: h
       real(c_double), intent(out) :: cf
       integer(c_int32_t), intent(out) :: clamped
     end function c_cf_table_lookup
     integer(c_int32_t) function c_cf_table_free(table) bind(C, name="pressridge_cf_table_free")
       import :: c_int32_t, c_ptr
       type(c_ptr), value :: table
     end function c_cf_table_free
     integer(c_int32_t) function c_ridge_table_open(path, len, table) &
          bind(C, name="pressridge_ridge_table_open")
       import :: c_int32_t, c_int64_t, c_char, c_ptr
       character(kind=c_char), intent(in) :: path(*)
       integer(c_int64_t), value :: len
       type(c_ptr), intent(out) :: table
     end function c_ridge_table_open
     integer(c_int32_t) function c_ridge_table_dims(table, nsets, nthickness, nvolume, nvar) &
          bind(C, name="pressridge_ridge_table_dims")
       import :: c_int32_t, c_int64_t, c_ptr
       type(c_ptr), value :: table
       integer(c_int64_t), intent(out) :: nsets, nthickness, nvolume, nvar
     end function c_ridge_table_dims
     integer(c_int32_t) function c_ridge_table_thickness(table, out, len) &
          bind(C, name="pressridge_ridge_table_thickness")
       import :: c_int32_t, c_int64_t, c_double, c_ptr
       type(c_ptr), value :: table
       real(c_double), intent(out) :: out(*)
       integer(c_int64_t), value :: len
     end function c_ridge_table_thickness
     integer(c_int32_t) function c_ridge_table_volume(table, out, len) &
          bind(C, name="pressridge_ridge_table_volume")
       import :: c_int32_t, c_int64_t, c_double, c_ptr
       type(c_ptr), value :: table
       real(c_double), intent(out) :: out(*)
       integer(c_int64_t), value :: len
     end function c_ridge_table_volume
     integer(c_int32_t) function c_ridge_table_set_name(table, set, buf, len, required) &
          bind(C, name="pressridge_ridge_table_set_name")
       import :: c_int32_t, c_int64_t, c_ptr
       type(c_ptr), value :: table
       integer(c_int64_t), value :: set
       type(c_ptr), value :: buf
       integer(c_int64_t), value :: len
       integer(c_int64_t), intent(out) :: required
     end function c_ridge_table_set_name
     integer(c_int32_t) function c_ridge_table_variable_name(table, index, buf, len, required) &
          bind(C, name="pressridge_ridge_table_variable_name")
       import :: c_int32_t, c_int64_t, c_ptr
       type(c_ptr), value :: table
       integer(c_int64_t), value :: index
       type(c_ptr), value :: buf
       integer(c_int64_t), value :: len
       integer(c_int64_t), intent(out) :: required
     end function c_ridge_table_variable_name
     integer(c_int32_t) function c_ridge_table_value(table, name, name_len, set, thickness, &
          volume, value, clamped) bind(C, name="pressridge_ridge_table_value")
       import :: c_int32_t, c_int64_t, c_char, c_double, c_ptr
       type(c_ptr), value :: table
       character(kind=c_char), intent(in) :: name(*)
       integer(c_int64_t), value :: name_len, set
       real(c_double), value :: thickness, volume
       real(c_double), intent(out) :: value
       integer(c_int32_t), intent(out) :: clamped
     end function c_ridge_table_value
     integer(c_int32_t) function c_ridge_table_cf(table, set, thickness, cf, clamped) &
          bind(C, name="pressridge_ridge_table_cf")
       import :: c_int32_t, c_int64_t, c_double, c_ptr
       type(c_ptr), value :: table
       integer(c_int64_t), value :: set
       real(c_double), value :: thickness
       real(c_double), intent(out) :: cf
       integer(c_int32_t), intent(out) :: clamped
     end function c_ridge_table_cf
     integer(c_int32_t) function c_ridge_table_cf_table(table, set, cf_table) &
          bind(C, name="pressridge_ridge_table_cf_table")
       import :: c_int32_t, c_int64_t, c_ptr
       type(c_ptr), value :: table
       integer(c_int64_t), value :: set
       type(c_ptr), intent(out) :: cf_table
     end function c_ridge_table_cf_table
     integer(c_int32_t) function c_ridge_table_friction_set(table, mu, mu_w, set) &
          bind(C, name="pressridge_ridge_table_friction_set")
       import :: c_int32_t, c_int64_t, c_double, c_ptr
       type(c_ptr), value :: table
       real(c_double), value :: mu, mu_w
       integer(c_int64_t), intent(out) :: set
     end function c_ridge_table_friction_set
     integer(c_int32_t) function c_ridge_table_free(table) &
          bind(C, name="pressridge_ridge_table_free")
       import :: c_int32_t, c_ptr
       type(c_ptr), value :: table
     end function c_ridge_table_free
     integer(c_int32_t) function c_scene_run(toml, len, run) bind(C, name="pressridge_scene_run")
       import :: c_int32_t, c_int64_t, c_char, c_ptr
       character(kind=c_char), intent(in) :: toml(*)
       integer(c_int64_t), value :: len
       type(c_ptr), intent(out) :: run
     end function c_scene_run
     integer(c_int32_t) function c_run_summary_json(run, buf, len, required) &
          bind(C, name="pressridge_run_summary_json")
       import :: c_int32_t, c_int64_t, c_ptr
       type(c_ptr), value :: run, buf
       integer(c_int64_t), value :: len
       integer(c_int64_t), intent(out) :: required
     end function c_run_summary_json
     integer(c_int32_t) function c_run_summary_value(run, key, len, value) &
          bind(C, name="pressridge_run_summary_value")
       import :: c_int32_t, c_int64_t, c_char, c_double, c_ptr
       type(c_ptr), value :: run
       character(kind=c_char), intent(in) :: key(*)
       integer(c_int64_t), value :: len
       real(c_double), intent(out) :: value
     end function c_run_summary_value
     integer(c_int32_t) function c_run_free(run) bind(C, name="pressridge_run_free")
       import :: c_int32_t, c_ptr
       type(c_ptr), value :: run
     end function c_run_free
  end interface

  !> Ice strength P (N/m) of many columns in one call: aicen(ncat, ncol) with x(ncol), or
  !> CICE's block layout aicen(nx, ny, ncat) with x(nx, ny).
  interface pressridge_strength
     module procedure strength_2d, strength_3d
  end interface pressridge_strength

  !> One ridging step of many columns in one call, in place; layouts as pressridge_strength.
  interface pressridge_ridge_step
     module procedure ridge_step_2d, ridge_step_3d
  end interface pressridge_ridge_step

  public :: pressridge_strength, pressridge_ridge_step
  public :: pressridge_ice_strength, pressridge_ridge_ice
  public :: pressridge_init_parameters, pressridge_get_parameters
  public :: pressridge_default_options, pressridge_options_set_cf_table
  public :: pressridge_version, pressridge_linked_abi_version, pressridge_last_error_message
  public :: pressridge_last_error_column
  public :: pressridge_cf_table_open, pressridge_cf_table_new, pressridge_cf_table_lookup
  public :: pressridge_cf_table_nodes, pressridge_cf_table_free
  public :: pressridge_cf_table_open_at_friction, pressridge_cf_table_friction
  public :: pressridge_ridge_table_open, pressridge_ridge_table_dims
  public :: pressridge_ridge_table_axes, pressridge_ridge_table_set_name
  public :: pressridge_ridge_table_variable_name, pressridge_ridge_table_value
  public :: pressridge_ridge_table_cf, pressridge_ridge_table_cf_table
  public :: pressridge_ridge_table_friction_set
  public :: pressridge_ridge_table_free
  public :: pressridge_scene_run, pressridge_run_summary_json, pressridge_run_summary_value
  public :: pressridge_run_free, pressridge_run_scene
  public :: pressridge_ridger_init, pressridge_ridger_free, pressridge_step_ridge
  public :: pressridge_step_ridge_cells

contains

  ! ------------------------------------------------------------------ errors and strings

  !> The message of the last failed pressridge call on this thread ('' after a success).
  function pressridge_last_error_message() result(msg)
    character(len=:), allocatable :: msg
    character(kind=c_char, len=:), allocatable, target :: buf
    integer(c_int64_t) :: need
    integer(c_int32_t) :: rc
    need = 1
    rc = c_last_error(c_null_ptr, 0_c_int64_t, need)
    allocate(character(kind=c_char, len=need) :: buf)
    rc = c_last_error(c_loc(buf), need, need)
    msg = buf(1:need - 1)
  end function pressridge_last_error_message

  !> The column (counting from 1) where the last failed call on this thread found bad input,
  !> or 0 when the error was not about one column. For the block layout aicen(nx, ny, ncat)
  !> column k is i = mod(k - 1, nx) + 1, j = (k - 1)/nx + 1.
  integer function pressridge_last_error_column()
    integer(c_int32_t) :: code, rc
    integer(c_int64_t) :: col
    rc = c_last_error_info(code, col)
    pressridge_last_error_column = int(col) + 1
  end function pressridge_last_error_column

  !> Hands a status to the caller: into ierr if present, else stop on error with the message.
  subroutine finish(rc, where, ierr)
    integer(c_int32_t), intent(in) :: rc
    character(len=*), intent(in) :: where
    integer, intent(out), optional :: ierr
    if (present(ierr)) then
       ierr = int(rc)
    else if (rc /= PRESSRIDGE_OK) then
       write (error_unit, '(a)') 'pressridge: '//where//': '//pressridge_last_error_message()
       error stop 'pressridge: error (pass ierr to handle it)'
    end if
  end subroutine finish

  !> Records an error found on the Fortran side (shapes) as this thread's last error.
  subroutine fail(code, message, where, ierr)
    integer, intent(in) :: code
    character(len=*), intent(in) :: message, where
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: rc
    rc = c_set_error(int(code, c_int32_t), message, int(len(message), c_int64_t))
    call finish(int(code, c_int32_t), where, ierr)
  end subroutine fail

  !> Reads a string by the required-length protocol. `kind`: 1 version, 2 set name,
  !> 3 variable name, 4 summary JSON.
  subroutine get_string(what, handle, index, out, rc)
    integer, intent(in) :: what
    type(c_ptr), intent(in) :: handle
    integer(c_int64_t), intent(in) :: index
    character(len=:), allocatable, intent(out) :: out
    integer(c_int32_t), intent(out) :: rc
    character(kind=c_char, len=:), allocatable, target :: buf
    integer(c_int64_t) :: need
    need = 0
    rc = call_string(what, handle, index, c_null_ptr, 0_c_int64_t, need)
    if (rc /= PRESSRIDGE_OK .and. rc /= PRESSRIDGE_ERR_BUFFER_TOO_SMALL) then
       out = ''
       return
    end if
    allocate(character(kind=c_char, len=need) :: buf)
    rc = call_string(what, handle, index, c_loc(buf), need, need)
    out = buf(1:need - 1)
  end subroutine get_string

  integer(c_int32_t) function call_string(what, handle, index, buf, len, need) result(rc)
    integer, intent(in) :: what
    type(c_ptr), intent(in) :: handle, buf
    integer(c_int64_t), intent(in) :: index, len
    integer(c_int64_t), intent(inout) :: need
    select case (what)
    case (1)
       rc = c_version(buf, len, need)
    case (2)
       rc = c_ridge_table_set_name(handle, index, buf, len, need)
    case (3)
       rc = c_ridge_table_variable_name(handle, index, buf, len, need)
    case default
       rc = c_run_summary_json(handle, buf, len, need)
    end select
  end function call_string

  !> The library version, e.g. '0.1.0'.
  function pressridge_version() result(v)
    character(len=:), allocatable :: v
    integer(c_int32_t) :: rc
    call get_string(1, c_null_ptr, 0_c_int64_t, v, rc)
  end function pressridge_version

  !> The C ABI version of the linked library (must equal PRESSRIDGE_ABI_VERSION).
  integer function pressridge_linked_abi_version()
    integer(c_int32_t) :: v, rc
    rc = c_abi_version(v)
    pressridge_linked_abi_version = int(v)
  end function pressridge_linked_abi_version

  ! ------------------------------------------------------------------ options

  !> CICE/Icepack's defaults from the library (the same as a fresh pressridge_options).
  subroutine pressridge_default_options(options, ierr)
    type(pressridge_options), intent(out) :: options
    integer, intent(out), optional :: ierr
    call finish(c_options_default(options), 'pressridge_default_options', ierr)
  end subroutine pressridge_default_options

  !> Makes `options` look C_f up in `table` (borrowed: keep it alive while in use).
  subroutine pressridge_options_set_cf_table(options, table)
    type(pressridge_options), intent(inout) :: options
    type(pressridge_cf_table), intent(in) :: table
    options%cf_source = PRESSRIDGE_CF_SOURCE_TABLE
    options%cf_table = table%ptr
  end subroutine pressridge_options_set_cf_table

  !> Sets the options of the Icepack-style calls pressridge_ice_strength and
  !> pressridge_ridge_ice, with Icepack's names: kstrength (0 Hibler 1979, 1 Rothrock),
  !> krdg_partic (0 Thorndike, 1 exponential), krdg_redist (0 uniform, 1 exponential),
  !> mu_rdg (m^0.5), Cf (1), Pstar (N/m2), Cstar (1), Cs (1), Gstar (1), astar (1), Hstar (m),
  !> maxraft (m), rhoi, rhow (kg/m3), gravit (m/s2), a C_f table (replaces Cf), or a whole
  !> options value (applied first). Call it once, before any OpenMP region.
  subroutine pressridge_init_parameters(kstrength, krdg_partic, krdg_redist, mu_rdg, Cf, &
       Pstar, Cstar, Cs, Gstar, astar, Hstar, maxraft, rhoi, rhow, gravit, cf_table, options)
    integer, intent(in), optional :: kstrength, krdg_partic, krdg_redist
    real(c_double), intent(in), optional :: mu_rdg, Cf, Pstar, Cstar, Cs, Gstar, astar, &
         Hstar, maxraft, rhoi, rhow, gravit
    type(pressridge_cf_table), intent(in), optional :: cf_table
    type(pressridge_options), intent(in), optional :: options
    if (present(options)) icepack_options = options
    if (present(kstrength)) icepack_options%strength_law = int(kstrength, c_int32_t)
    if (present(krdg_partic)) icepack_options%participation = int(krdg_partic, c_int32_t)
    if (present(krdg_redist)) icepack_options%redistribution = int(krdg_redist, c_int32_t)
    if (present(mu_rdg)) icepack_options%params%mu_rdg = mu_rdg
    if (present(Cf)) then
       icepack_options%cf = Cf
       icepack_options%cf_source = PRESSRIDGE_CF_SOURCE_CONSTANT
    end if
    if (present(Pstar)) icepack_options%params%pstar = Pstar
    if (present(Cstar)) icepack_options%params%cstar = Cstar
    if (present(Cs)) icepack_options%params%cs = Cs
    if (present(Gstar)) icepack_options%params%gstar = Gstar
    if (present(astar)) icepack_options%params%astar = astar
    if (present(Hstar)) icepack_options%params%hstar = Hstar
    if (present(maxraft)) icepack_options%params%maxraft = maxraft
    if (present(rhoi)) icepack_options%params%rhoi = rhoi
    if (present(rhow)) icepack_options%params%rhow = rhow
    if (present(gravit)) icepack_options%params%gravit = gravit
    if (present(cf_table)) call pressridge_options_set_cf_table(icepack_options, cf_table)
  end subroutine pressridge_init_parameters

  !> The options of the Icepack-style calls.
  subroutine pressridge_get_parameters(options)
    type(pressridge_options), intent(out) :: options
    options = icepack_options
  end subroutine pressridge_get_parameters

  ! ------------------------------------------------------------------ strength

  !> Icepack-compatible: the same arguments as icepack_ice_strength (aice, vice, aice0, aicen,
  !> vicen, strength), so a host swaps one call. Options from pressridge_init_parameters
  !> (CICE's defaults otherwise). strength (N/m) is overwritten, not accumulated (CICE sets it
  !> to 0 before its call). aice and vice are accepted for compatibility; the library uses
  !> sum(aicen) and sum(vicen). Errors (NaN, negative, |aice0 + sum(aicen) - 1| > 1e-6) come
  !> back in ierr, or stop the program when ierr is absent.
  subroutine pressridge_ice_strength(aice, vice, aice0, aicen, vicen, strength, ierr)
    real(c_double), intent(in) :: aice, vice
    real(c_double), intent(in), target :: aice0
    real(c_double), intent(in), contiguous, target :: aicen(:), vicen(:)
    real(c_double), intent(inout), target :: strength
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: rc
    if (size(vicen) /= size(aicen)) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'vicen and aicen differ in size', &
            'pressridge_ice_strength', ierr)
       return
    end if
    if (size(aicen) == 0) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'aicen is empty (ncat = 0)', &
            'pressridge_ice_strength', ierr)
       return
    end if
    rc = c_strength_cell(size(aicen, kind=c_int64_t), c_loc(aicen), c_loc(vicen), aice0, &
         c_loc(icepack_options), c_loc(strength))
    call finish(rc, 'pressridge_ice_strength', ierr)
  end subroutine pressridge_ice_strength

  !> Per-column arrays (aice0, valid, outputs) must have `ncol` elements.
  logical function sized(n, ncol, name, where, ierr)
    integer, intent(in) :: n, ncol
    character(len=*), intent(in) :: name, where
    integer, intent(out), optional :: ierr
    character(len=24) :: a, b
    sized = n == ncol
    if (.not. sized) then
       write (a, '(i0)') n
       write (b, '(i0)') ncol
       call fail(PRESSRIDGE_ERR_BAD_SIZE, name//' has '//trim(a)//' elements, expected ncol = ' &
            //trim(b), where, ierr)
    end if
  end function sized

  subroutine strength_common(g, aicen, vicen, strength, aice0, options, valid, &
       cf_clamped_columns, where, ierr)
    type(c_grid), intent(in) :: g
    type(c_ptr), intent(in) :: aicen, vicen, strength, aice0
    type(pressridge_options), intent(in), optional, target :: options
    logical, intent(in), optional :: valid(:)
    integer, intent(out), optional :: cf_clamped_columns
    character(len=*), intent(in) :: where
    integer, intent(out), optional :: ierr
    integer(c_int32_t), allocatable, target :: v(:)
    integer(c_int64_t), target :: nclamped
    type(c_ptr) :: pv, po
    integer(c_int32_t) :: rc
    pv = c_null_ptr
    if (present(valid)) then
       allocate(v(size(valid)))
       v = merge(1_c_int32_t, 0_c_int32_t, valid)
       if (size(v) > 0) pv = c_loc(v)
    end if
    po = c_loc(icepack_options)
    if (present(options)) po = c_loc(options)
    rc = c_strength(g, aicen, vicen, aice0, pv, po, strength, c_loc(nclamped))
    if (rc == PRESSRIDGE_OK .and. present(cf_clamped_columns)) cf_clamped_columns = int(nclamped)
    call finish(rc, where, ierr)
  end subroutine strength_common

  !> Strength P (N/m) of ncol columns: aicen(ncat, ncol) (1), vicen(ncat, ncol) (m),
  !> strength(ncol); optional aice0(ncol) (else 1 - sum(aicen)), options (else those of
  !> pressridge_init_parameters, i.e. CICE's defaults), valid(ncol) (.false. columns get
  !> options%fill and are not checked), cf_clamped_columns (columns where a C_f table was
  !> queried outside its range).
  subroutine strength_2d(aicen, vicen, strength, aice0, options, valid, cf_clamped_columns, ierr)
    real(c_double), intent(in), contiguous, target :: aicen(:, :), vicen(:, :)
    real(c_double), intent(out), contiguous, target :: strength(:)
    real(c_double), intent(in), contiguous, target, optional :: aice0(:)
    type(pressridge_options), intent(in), optional, target :: options
    logical, intent(in), optional :: valid(:)
    integer, intent(out), optional :: cf_clamped_columns
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_strength'
    integer :: ncat, ncol
    type(c_ptr) :: pa0
    ncat = size(aicen, 1)
    ncol = size(aicen, 2)
    if (any(shape(vicen) /= shape(aicen))) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'vicen and aicen differ in shape', where, ierr)
       return
    end if
    if (.not. sized(size(strength), ncol, 'strength', where, ierr)) return
    pa0 = c_null_ptr
    if (present(aice0)) then
       if (.not. sized(size(aice0), ncol, 'aice0', where, ierr)) return
       if (ncol > 0) pa0 = c_loc(aice0)
    end if
    if (present(valid)) then
       if (.not. sized(size(valid), ncol, 'valid', where, ierr)) return
    end if
    call strength_common(grid_2d(ncat, ncol), ptr2(aicen), ptr2(vicen), ptr1(strength), pa0, &
         options, valid, cf_clamped_columns, where, ierr)
  end subroutine strength_2d

  !> As strength_2d in CICE's block layout: aicen(nx, ny, ncat), vicen(nx, ny, ncat), and
  !> strength, aice0, valid of shape (nx, ny).
  subroutine strength_3d(aicen, vicen, strength, aice0, options, valid, cf_clamped_columns, ierr)
    real(c_double), intent(in), contiguous, target :: aicen(:, :, :), vicen(:, :, :)
    real(c_double), intent(out), contiguous, target :: strength(:, :)
    real(c_double), intent(in), contiguous, target, optional :: aice0(:, :)
    type(pressridge_options), intent(in), optional, target :: options
    logical, intent(in), optional :: valid(:, :)
    integer, intent(out), optional :: cf_clamped_columns
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_strength'
    integer :: ncat, ncol
    type(c_ptr) :: pa0
    ncol = size(aicen, 1) * size(aicen, 2)
    ncat = size(aicen, 3)
    if (any(shape(vicen) /= shape(aicen))) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'vicen and aicen differ in shape', where, ierr)
       return
    end if
    if (any(shape(strength) /= shape(aicen(:, :, 1)))) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'strength must have the shape (nx, ny) of aicen', &
            where, ierr)
       return
    end if
    pa0 = c_null_ptr
    if (present(aice0)) then
       if (any(shape(aice0) /= shape(strength))) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'aice0 must have the shape (nx, ny) of aicen', &
               where, ierr)
          return
       end if
       if (ncol > 0) pa0 = c_loc(aice0)
    end if
    if (present(valid)) then
       if (any(shape(valid) /= shape(strength))) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'valid must have the shape (nx, ny) of aicen', &
               where, ierr)
          return
       end if
       call strength_common(grid_3d(ncat, ncol), ptr3(aicen), ptr3(vicen), ptr2(strength), &
            pa0, options, reshape(valid, [ncol]), cf_clamped_columns, where, ierr)
    else
       call strength_common(grid_3d(ncat, ncol), ptr3(aicen), ptr3(vicen), ptr2(strength), &
            pa0, options, cf_clamped_columns=cf_clamped_columns, where=where, ierr=ierr)
    end if
  end subroutine strength_3d

  ! ------------------------------------------------------------------ ridging

  !> Icepack-style ridging step of one cell (ridge_ice without snow, tracers and fluxes):
  !> dt (s), hin_max(0:ncat) (m), rdg_conv, rdg_shear (1/s), aicen(ncat) (1), vicen(ncat) (m)
  !> and aice0 (1) updated in place; optional rates dardg1dt, dardg2dt (1/s), dvirdgdt (m/s),
  !> opening, closing (1/s). Options from pressridge_init_parameters.
  subroutine pressridge_ridge_ice(dt, hin_max, rdg_conv, rdg_shear, aicen, vicen, aice0, &
       dardg1dt, dardg2dt, dvirdgdt, opening, closing, ierr)
    real(c_double), intent(in) :: dt
    real(c_double), intent(in), contiguous, target :: hin_max(0:)
    real(c_double), intent(in), target :: rdg_conv, rdg_shear
    real(c_double), intent(inout), contiguous, target :: aicen(:), vicen(:)
    real(c_double), intent(inout), target :: aice0
    real(c_double), intent(out), optional, target :: dardg1dt, dardg2dt, dvirdgdt, opening, closing
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_ridge_ice'
    type(c_grid) :: g
    type(c_rates) :: r
    integer(c_int64_t) :: n
    n = size(aicen, kind=c_int64_t)
    if (size(vicen) /= n .or. n == 0) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'vicen and aicen must have the same size ncat > 0', &
            where, ierr)
       return
    end if
    g = c_grid(n, 1_c_int64_t, 1_c_int64_t, n, n, 1_c_int64_t, 1_c_int64_t)
    if (present(dardg1dt)) r%dardg1dt = c_loc(dardg1dt)
    if (present(dardg2dt)) r%dardg2dt = c_loc(dardg2dt)
    if (present(dvirdgdt)) r%dvirdgdt = c_loc(dvirdgdt)
    if (present(opening)) r%opening = c_loc(opening)
    if (present(closing)) r%closing = c_loc(closing)
    call finish(c_ridge_step(g, c_loc(aicen), c_loc(vicen), c_loc(aice0), c_loc(hin_max), &
         size(hin_max, kind=c_int64_t), c_loc(rdg_conv), c_loc(rdg_shear), dt, c_null_ptr, &
         c_loc(icepack_options), r), where, ierr)
  end subroutine pressridge_ridge_ice

  subroutine ridge_common(g, aicen, vicen, aice0, convergence, shear, dt, hin_max, options, &
       valid, r, where, ierr)
    type(c_grid), intent(in) :: g
    type(c_ptr), intent(in) :: aicen, vicen, aice0, convergence, shear
    real(c_double), intent(in) :: dt
    real(c_double), intent(in), optional, contiguous, target :: hin_max(:)
    type(pressridge_options), intent(in), optional, target :: options
    logical, intent(in), optional :: valid(:)
    type(c_rates), intent(in) :: r
    character(len=*), intent(in) :: where
    integer, intent(out), optional :: ierr
    integer(c_int32_t), allocatable, target :: v(:)
    type(c_ptr) :: pv, po, ph
    integer(c_int64_t) :: nb
    pv = c_null_ptr
    if (present(valid)) then
       allocate(v(size(valid)))
       v = merge(1_c_int32_t, 0_c_int32_t, valid)
       if (size(v) > 0) pv = c_loc(v)
    end if
    po = c_loc(icepack_options)
    if (present(options)) po = c_loc(options)
    ph = c_null_ptr
    nb = 0
    if (present(hin_max)) then
       nb = size(hin_max, kind=c_int64_t)
       if (nb > 0) ph = c_loc(hin_max)
       if (nb == 0) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'hin_max is empty', where, ierr)
          return
       end if
    end if
    call finish(c_ridge_step(g, aicen, vicen, aice0, ph, nb, convergence, shear, dt, pv, po, r), &
         where, ierr)
  end subroutine ridge_common

  !> One ridging step of dt (s) over ncol columns, in place: aicen(ncat, ncol) (1),
  !> vicen(ncat, ncol) (m), aice0(ncol) (1); convergence(ncol), shear(ncol) (1/s, >= 0);
  !> optional hin_max(0:ncat) (m; else CICE's default bounds), options, valid(ncol), and the
  !> rates closing, opening, dardg1dt, dardg2dt (1/s), dvirdgdt (m/s), each (ncol).
  subroutine ridge_step_2d(aicen, vicen, aice0, convergence, shear, dt, hin_max, options, &
       valid, closing, opening, dardg1dt, dardg2dt, dvirdgdt, ierr)
    real(c_double), intent(inout), contiguous, target :: aicen(:, :), vicen(:, :), aice0(:)
    real(c_double), intent(in), contiguous, target :: convergence(:), shear(:)
    real(c_double), intent(in) :: dt
    real(c_double), intent(in), optional, contiguous, target :: hin_max(:)
    type(pressridge_options), intent(in), optional, target :: options
    logical, intent(in), optional :: valid(:)
    real(c_double), intent(out), optional, contiguous, target :: closing(:), opening(:), &
         dardg1dt(:), dardg2dt(:), dvirdgdt(:)
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_ridge_step'
    type(c_rates) :: r
    integer :: ncat, ncol
    ncat = size(aicen, 1)
    ncol = size(aicen, 2)
    if (any(shape(vicen) /= shape(aicen))) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'vicen and aicen differ in shape', where, ierr)
       return
    end if
    if (.not. sized(size(aice0), ncol, 'aice0', where, ierr)) return
    if (.not. sized(size(convergence), ncol, 'convergence', where, ierr)) return
    if (.not. sized(size(shear), ncol, 'shear', where, ierr)) return
    if (present(valid)) then
       if (.not. sized(size(valid), ncol, 'valid', where, ierr)) return
    end if
    if (.not. ok1('closing', closing)) return
    if (.not. ok1('opening', opening)) return
    if (.not. ok1('dardg1dt', dardg1dt)) return
    if (.not. ok1('dardg2dt', dardg2dt)) return
    if (.not. ok1('dvirdgdt', dvirdgdt)) return
    r = rate_ptrs(ncol, closing, opening, dardg1dt, dardg2dt, dvirdgdt)
    call ridge_common(grid_2d(ncat, ncol), ptr2(aicen), ptr2(vicen), ptr1(aice0), &
         ptr1(convergence), ptr1(shear), dt, hin_max, options, valid, r, where, ierr)
  contains
    !> An absent rate, or one of ncol values.
    logical function ok1(name, x)
      character(len=*), intent(in) :: name
      real(c_double), intent(in), optional :: x(:)
      ok1 = .true.
      if (present(x)) ok1 = sized(size(x), ncol, name, where, ierr)
    end function ok1
  end subroutine ridge_step_2d

  !> As ridge_step_2d in CICE's block layout: aicen(nx, ny, ncat), vicen(nx, ny, ncat), and
  !> aice0, convergence, shear, valid and the rates of shape (nx, ny).
  subroutine ridge_step_3d(aicen, vicen, aice0, convergence, shear, dt, hin_max, options, &
       valid, closing, opening, dardg1dt, dardg2dt, dvirdgdt, ierr)
    real(c_double), intent(inout), contiguous, target :: aicen(:, :, :), vicen(:, :, :), &
         aice0(:, :)
    real(c_double), intent(in), contiguous, target :: convergence(:, :), shear(:, :)
    real(c_double), intent(in) :: dt
    real(c_double), intent(in), optional, contiguous, target :: hin_max(:)
    type(pressridge_options), intent(in), optional, target :: options
    logical, intent(in), optional :: valid(:, :)
    real(c_double), intent(out), optional, contiguous, target :: closing(:, :), opening(:, :), &
         dardg1dt(:, :), dardg2dt(:, :), dvirdgdt(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_ridge_step'
    type(c_rates) :: r
    integer :: ncat, ncol, s(2)
    s = [size(aicen, 1), size(aicen, 2)]
    ncol = s(1) * s(2)
    ncat = size(aicen, 3)
    if (any(shape(vicen) /= shape(aicen))) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'vicen and aicen differ in shape', where, ierr)
       return
    end if
    if (.not. same2(aice0, 'aice0')) return
    if (.not. same2(convergence, 'convergence')) return
    if (.not. same2(shear, 'shear')) return
    if (present(valid)) then
       if (any(shape(valid) /= s)) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'valid must have the shape (nx, ny) of aicen', &
               where, ierr)
          return
       end if
    end if
    if (.not. ok2('closing', closing)) return
    if (.not. ok2('opening', opening)) return
    if (.not. ok2('dardg1dt', dardg1dt)) return
    if (.not. ok2('dardg2dt', dardg2dt)) return
    if (.not. ok2('dvirdgdt', dvirdgdt)) return
    r = rate_ptrs(ncol, closing, opening, dardg1dt, dardg2dt, dvirdgdt)
    if (present(valid)) then
       call ridge_common(grid_3d(ncat, ncol), ptr3(aicen), ptr3(vicen), ptr2(aice0), &
            ptr2(convergence), ptr2(shear), dt, hin_max, options, reshape(valid, [ncol]), r, &
            where, ierr)
    else
       call ridge_common(grid_3d(ncat, ncol), ptr3(aicen), ptr3(vicen), ptr2(aice0), &
            ptr2(convergence), ptr2(shear), dt, hin_max, options, r=r, where=where, ierr=ierr)
    end if
  contains
    logical function same2(x, name)
      real(c_double), intent(in) :: x(:, :)
      character(len=*), intent(in) :: name
      same2 = all(shape(x) == s)
      if (.not. same2) call fail(PRESSRIDGE_ERR_BAD_SIZE, name// &
           ' must have the shape (nx, ny) of aicen', where, ierr)
    end function same2
    !> An absent rate, or one of the shape (nx, ny) of aicen.
    logical function ok2(name, x)
      character(len=*), intent(in) :: name
      real(c_double), intent(in), optional :: x(:, :)
      ok2 = .true.
      if (present(x)) ok2 = same2(x, name)
    end function ok2
  end subroutine ridge_step_3d

  !> C pointers to the optional rates of a ridging call, null where absent; each present
  !> array is contiguous and holds ncol values (its caller checked the shape). Assumed
  !> size, so one routine serves the (ncol) and the (nx, ny) layouts.
  type(c_rates) function rate_ptrs(ncol, closing, opening, dardg1dt, dardg2dt, dvirdgdt) &
       result(r)
    integer, intent(in) :: ncol
    real(c_double), intent(in), optional, target :: closing(*), opening(*), dardg1dt(*), &
         dardg2dt(*), dvirdgdt(*)
    if (ncol == 0) return
    if (present(closing)) r%closing = c_loc(closing(1))
    if (present(opening)) r%opening = c_loc(opening(1))
    if (present(dardg1dt)) r%dardg1dt = c_loc(dardg1dt(1))
    if (present(dardg2dt)) r%dardg2dt = c_loc(dardg2dt(1))
    if (present(dvirdgdt)) r%dvirdgdt = c_loc(dvirdgdt(1))
  end function rate_ptrs

  ! ------------------------------------------------------------------ layouts

  !> aicen(ncat, ncol), x(ncol), contiguous. Zero sizes are passed on for the library to
  !> reject with a message.
  type(c_grid) function grid_2d(ncat, ncol) result(g)
    integer, intent(in) :: ncat, ncol
    g = c_grid(int(ncat, c_int64_t), int(ncol, c_int64_t), 1_c_int64_t, &
         int(max(ncat, 1), c_int64_t), int(ncat, c_int64_t) * int(ncol, c_int64_t), &
         1_c_int64_t, int(ncol, c_int64_t))
  end function grid_2d

  !> aicen(nx, ny, ncat) with ncol = nx*ny, x(nx, ny), contiguous.
  type(c_grid) function grid_3d(ncat, ncol) result(g)
    integer, intent(in) :: ncat, ncol
    g = c_grid(int(ncat, c_int64_t), int(ncol, c_int64_t), int(max(ncol, 1), c_int64_t), &
         1_c_int64_t, int(ncat, c_int64_t) * int(ncol, c_int64_t), 1_c_int64_t, &
         int(ncol, c_int64_t))
  end function grid_3d

  type(c_ptr) function ptr1(x)
    real(c_double), intent(in), contiguous, target :: x(:)
    ptr1 = c_null_ptr
    if (size(x) > 0) ptr1 = c_loc(x)
  end function ptr1

  type(c_ptr) function ptr2(x)
    real(c_double), intent(in), contiguous, target :: x(:, :)
    ptr2 = c_null_ptr
    if (size(x) > 0) ptr2 = c_loc(x)
  end function ptr2

  type(c_ptr) function ptr3(x)
    real(c_double), intent(in), contiguous, target :: x(:, :, :)
    ptr3 = c_null_ptr
    if (size(x) > 0) ptr3 = c_loc(x)
  end function ptr3

  ! ------------------------------------------------------------------ C_f tables

  !> Opens a C_f table (NetCDF with 1-D `thickness` (m) and `cf` (1)).
  subroutine pressridge_cf_table_open(path, table, ierr)
    character(len=*), intent(in) :: path
    type(pressridge_cf_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    call finish(c_cf_table_open(path, len(path, kind=c_int64_t), table%ptr), &
         'pressridge_cf_table_open('//path//')', ierr)
  end subroutine pressridge_cf_table_open

  !> The C_f at friction mu (between blocks above the water line) and mu_w (below it; both
  !> dimensionless) of a ridging table of `pressridge tabulate`; PRESSRIDGE_ERR_NOT_FOUND,
  !> with the pairs the table has in the message, when it has no set at that friction.
  subroutine pressridge_cf_table_open_at_friction(path, mu, mu_w, table, ierr)
    character(len=*), intent(in) :: path
    real(c_double), intent(in) :: mu, mu_w
    type(pressridge_cf_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    call finish(c_cf_table_open_at_friction(path, len(path, kind=c_int64_t), mu, mu_w, &
         table%ptr), 'pressridge_cf_table_open_at_friction('//path//')', ierr)
  end subroutine pressridge_cf_table_open_at_friction

  !> The friction pair (mu, mu_w; dimensionless) a C_f table is for; known is .false. (and
  !> mu, mu_w NaN) when the table does not say.
  subroutine pressridge_cf_table_friction(table, mu, mu_w, known, ierr)
    type(pressridge_cf_table), intent(in) :: table
    real(c_double), intent(out) :: mu, mu_w
    logical, intent(out) :: known
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: k
    k = 0
    call finish(c_cf_table_friction(table%ptr, mu, mu_w, k), 'pressridge_cf_table_friction', &
         ierr)
    known = k /= 0
  end subroutine pressridge_cf_table_friction

  !> A C_f table from nodes: thickness (m, strictly increasing) and cf (1, > 0).
  subroutine pressridge_cf_table_new(thickness, cf, table, ierr)
    real(c_double), intent(in) :: thickness(:), cf(:)
    type(pressridge_cf_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    real(c_double) :: t1(max(size(thickness), 1)), c1(max(size(thickness), 1))
    if (size(cf) /= size(thickness)) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'cf and thickness differ in size', &
            'pressridge_cf_table_new', ierr)
       return
    end if
    t1(1:size(thickness)) = thickness
    c1(1:size(cf)) = cf
    call finish(c_cf_table_new(t1, c1, size(thickness, kind=c_int64_t), table%ptr), &
         'pressridge_cf_table_new', ierr)
  end subroutine pressridge_cf_table_new

  !> C_f (1) at ridging-ice thickness h (m); clamped is .true. outside the table's range.
  subroutine pressridge_cf_table_lookup(table, h, cf, clamped, ierr)
    type(pressridge_cf_table), intent(in) :: table
    real(c_double), intent(in) :: h
    real(c_double), intent(out) :: cf
    logical, intent(out), optional :: clamped
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: c, rc
    rc = c_cf_table_lookup(table%ptr, h, cf, c)
    if (present(clamped)) clamped = c /= 0
    call finish(rc, 'pressridge_cf_table_lookup', ierr)
  end subroutine pressridge_cf_table_lookup

  !> The nodes of a C_f table: thickness (m) and cf (1).
  subroutine pressridge_cf_table_nodes(table, thickness, cf, ierr)
    type(pressridge_cf_table), intent(in) :: table
    real(c_double), allocatable, intent(out) :: thickness(:), cf(:)
    integer, intent(out), optional :: ierr
    integer(c_int64_t) :: n
    integer(c_int32_t) :: rc
    rc = c_cf_table_len(table%ptr, n)
    if (rc /= PRESSRIDGE_OK) then
       call finish(rc, 'pressridge_cf_table_nodes', ierr)
       return
    end if
    allocate(thickness(n), cf(n))
    call finish(c_cf_table_nodes(table%ptr, thickness, cf, n), 'pressridge_cf_table_nodes', ierr)
  end subroutine pressridge_cf_table_nodes

  !> Releases a C_f table (no options may use it afterwards).
  subroutine pressridge_cf_table_free(table)
    type(pressridge_cf_table), intent(inout) :: table
    integer(c_int32_t) :: rc
    rc = c_cf_table_free(table%ptr)
    table%ptr = c_null_ptr
  end subroutine pressridge_cf_table_free

  ! ------------------------------------------------------------------ ridging tables

  !> Opens a ridging lookup table written by `pressridge tabulate`.
  subroutine pressridge_ridge_table_open(path, table, ierr)
    character(len=*), intent(in) :: path
    type(pressridge_ridge_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    call finish(c_ridge_table_open(path, len(path, kind=c_int64_t), table%ptr), &
         'pressridge_ridge_table_open('//path//')', ierr)
  end subroutine pressridge_ridge_table_open

  !> Numbers of sets, thickness nodes, volume nodes and fields.
  subroutine pressridge_ridge_table_dims(table, nsets, nthickness, nvolume, nvariables, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(out) :: nsets, nthickness, nvolume, nvariables
    integer, intent(out), optional :: ierr
    integer(c_int64_t) :: a, b, c, d
    integer(c_int32_t) :: rc
    a = 0; b = 0; c = 0; d = 0
    rc = c_ridge_table_dims(table%ptr, a, b, c, d)
    nsets = int(a); nthickness = int(b); nvolume = int(c); nvariables = int(d)
    call finish(rc, 'pressridge_ridge_table_dims', ierr)
  end subroutine pressridge_ridge_table_dims

  !> The thickness (m) and volume (m3/m) axes.
  subroutine pressridge_ridge_table_axes(table, thickness, volume, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    real(c_double), allocatable, intent(out) :: thickness(:), volume(:)
    integer, intent(out), optional :: ierr
    integer :: ns, nh, nv, nf, e
    call pressridge_ridge_table_dims(table, ns, nh, nv, nf, e)
    if (e /= PRESSRIDGE_OK) then
       call finish(int(e, c_int32_t), 'pressridge_ridge_table_axes', ierr)
       return
    end if
    allocate(thickness(nh), volume(nv))
    e = c_ridge_table_thickness(table%ptr, thickness, int(nh, c_int64_t))
    if (e == PRESSRIDGE_OK) e = c_ridge_table_volume(table%ptr, volume, int(nv, c_int64_t))
    call finish(int(e, c_int32_t), 'pressridge_ridge_table_axes', ierr)
  end subroutine pressridge_ridge_table_axes

  !> The label of set `set` (from 1).
  subroutine pressridge_ridge_table_set_name(table, set, name, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(in) :: set
    character(len=:), allocatable, intent(out) :: name
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: rc
    call get_string(2, table%ptr, int(set - 1, c_int64_t), name, rc)
    call finish(rc, 'pressridge_ridge_table_set_name', ierr)
  end subroutine pressridge_ridge_table_set_name

  !> The name of field `index` (from 1, sorted by name).
  subroutine pressridge_ridge_table_variable_name(table, index, name, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(in) :: index
    character(len=:), allocatable, intent(out) :: name
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: rc
    call get_string(3, table%ptr, int(index - 1, c_int64_t), name, rc)
    call finish(rc, 'pressridge_ridge_table_variable_name', ierr)
  end subroutine pressridge_ridge_table_variable_name

  !> Field `name` of set `set` (from 1) at thickness (m) and volume (m3/m), interpolated
  !> (the field's units; NaN where the table has no data); clamped outside the table.
  subroutine pressridge_ridge_table_value(table, name, set, thickness, volume, value, clamped, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    character(len=*), intent(in) :: name
    integer, intent(in) :: set
    real(c_double), intent(in) :: thickness, volume
    real(c_double), intent(out) :: value
    logical, intent(out), optional :: clamped
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: c, rc
    c = 0
    rc = c_ridge_table_value(table%ptr, name, len(name, kind=c_int64_t), &
         int(set - 1, c_int64_t), thickness, volume, value, c)
    if (present(clamped)) clamped = c /= 0
    call finish(rc, 'pressridge_ridge_table_value('//name//')', ierr)
  end subroutine pressridge_ridge_table_value

  !> C_f (1) of set `set` (from 1) at ridging-ice thickness (m).
  subroutine pressridge_ridge_table_cf(table, set, thickness, cf, clamped, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(in) :: set
    real(c_double), intent(in) :: thickness
    real(c_double), intent(out) :: cf
    logical, intent(out), optional :: clamped
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: c, rc
    c = 0
    rc = c_ridge_table_cf(table%ptr, int(set - 1, c_int64_t), thickness, cf, c)
    if (present(clamped)) clamped = c /= 0
    call finish(rc, 'pressridge_ridge_table_cf', ierr)
  end subroutine pressridge_ridge_table_cf

  !> The C_f of set `set` (from 1) as a new C_f table for the strength options.
  subroutine pressridge_ridge_table_cf_table(table, set, cf_table, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(in) :: set
    type(pressridge_cf_table), intent(out) :: cf_table
    integer, intent(out), optional :: ierr
    call finish(c_ridge_table_cf_table(table%ptr, int(set - 1, c_int64_t), cf_table%ptr), &
         'pressridge_ridge_table_cf_table', ierr)
  end subroutine pressridge_ridge_table_cf_table

  !> The set (1-based) of a ridging table at friction mu, mu_w (dimensionless);
  !> PRESSRIDGE_ERR_NOT_FOUND when the table has no such set or no friction coordinates.
  subroutine pressridge_ridge_table_friction_set(table, mu, mu_w, set, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    real(c_double), intent(in) :: mu, mu_w
    integer, intent(out) :: set
    integer, intent(out), optional :: ierr
    integer(c_int64_t) :: s0
    s0 = -1
    call finish(c_ridge_table_friction_set(table%ptr, mu, mu_w, s0), &
         'pressridge_ridge_table_friction_set', ierr)
    set = int(s0) + 1
  end subroutine pressridge_ridge_table_friction_set

  !> Releases a ridging lookup table.
  subroutine pressridge_ridge_table_free(table)
    type(pressridge_ridge_table), intent(inout) :: table
    integer(c_int32_t) :: rc
    rc = c_ridge_table_free(table%ptr)
    table%ptr = c_null_ptr
  end subroutine pressridge_ridge_table_free

  ! ------------------------------------------------------------------ simulator

  !> Runs the scene given as TOML text (the format of data/scenes/*.toml) on this thread.
  subroutine pressridge_scene_run(toml, run, ierr)
    character(len=*), intent(in) :: toml
    type(pressridge_run), intent(out) :: run
    integer, intent(out), optional :: ierr
    call finish(c_scene_run(toml, len(toml, kind=c_int64_t), run%ptr), 'pressridge_scene_run', &
         ierr)
  end subroutine pressridge_scene_run

  !> The run's summary as JSON (summary.json of `pressridge simulate`).
  subroutine pressridge_run_summary_json(run, json, ierr)
    type(pressridge_run), intent(in) :: run
    character(len=:), allocatable, intent(out) :: json
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: rc
    call get_string(4, run%ptr, 0_c_int64_t, json, rc)
    call finish(rc, 'pressridge_run_summary_json', ierr)
  end subroutine pressridge_run_summary_json

  !> One number of the run's summary by key (e.g. 'work' in J/m, 'steps').
  subroutine pressridge_run_summary_value(run, key, value, ierr)
    type(pressridge_run), intent(in) :: run
    character(len=*), intent(in) :: key
    real(c_double), intent(out) :: value
    integer, intent(out), optional :: ierr
    call finish(c_run_summary_value(run%ptr, key, len(key, kind=c_int64_t), value), &
         'pressridge_run_summary_value('//key//')', ierr)
  end subroutine pressridge_run_summary_value

  !> Releases a run.
  subroutine pressridge_run_free(run)
    type(pressridge_run), intent(inout) :: run
    integer(c_int32_t) :: rc
    rc = c_run_free(run%ptr)
    run%ptr = c_null_ptr
  end subroutine pressridge_run_free

  !> Runs a scene (TOML text) and returns its summary as JSON in one call.
  subroutine pressridge_run_scene(toml, json, ierr)
    character(len=*), intent(in) :: toml
    character(len=:), allocatable, intent(out) :: json
    integer, intent(out), optional :: ierr
    type(pressridge_run) :: run
    integer :: e
    json = ''
    call pressridge_scene_run(toml, run, e)
    if (e == PRESSRIDGE_OK) then
       call pressridge_run_summary_json(run, json, e)
       call pressridge_run_free(run)
    end if
    call finish(int(e, c_int32_t), 'pressridge_run_scene', ierr)
  end subroutine pressridge_run_scene

  ! ------------------------------------------------- the complete ridging step (issue 15)

  !> Initialises a ridging set-up once: ncat categories, the CICE tracer layout with nilyr ice
  !> and nslyr snow layers and the optional tracers (Icepack's flags), the options (default:
  !> CICE's; participation, redistribution and params are used) and Icepack's docleanup and
  !> dorebin (default .true.). Optionally returns the layout as Icepack's arrays (ntrcr and,
  !> sized ntrcr or more, trcr_depend, trcr_base(:, 3), n_trcr_strata, nt_strata(:, 2)).
  subroutine pressridge_ridger_init(ridger, ncat, nilyr, nslyr, tr_iage, tr_FY, tr_lvl, &
       tr_pond_lvl, options, docleanup, dorebin, ntrcr, trcr_depend, trcr_base, &
       n_trcr_strata, nt_strata, ierr)
    type(pressridge_ridger), intent(out) :: ridger
    integer, intent(in) :: ncat, nilyr, nslyr
    logical, intent(in) :: tr_iage, tr_FY, tr_lvl, tr_pond_lvl
    type(pressridge_options), intent(in), optional, target :: options
    logical, intent(in), optional :: docleanup, dorebin
    integer, intent(out), optional :: ntrcr
    integer(c_int32_t), intent(out), optional, contiguous, target :: trcr_depend(:), &
         n_trcr_strata(:), nt_strata(:, :)
    real(c_double), intent(out), optional, contiguous, target :: trcr_base(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_ridger_init'
    integer(c_int32_t) :: flags, clean, rebin, rc
    integer(c_int64_t) :: nt, len
    type(c_ptr) :: o, pd, pb, pn, ps
    flags = 0
    if (tr_iage) flags = flags + PRESSRIDGE_TRACER_AGE
    if (tr_FY) flags = flags + PRESSRIDGE_TRACER_FIRST_YEAR
    if (tr_lvl) flags = flags + PRESSRIDGE_TRACER_LEVEL_ICE
    if (tr_pond_lvl) flags = flags + PRESSRIDGE_TRACER_PONDS
    clean = 1
    rebin = 1
    if (present(docleanup)) then
       if (.not. docleanup) clean = 0
    end if
    if (present(dorebin)) then
       if (.not. dorebin) rebin = 0
    end if
    o = c_null_ptr
    if (present(options)) o = c_loc(options)
    rc = c_ridger_new(int(ncat, c_int64_t), int(nilyr, c_int64_t), int(nslyr, c_int64_t), &
         flags, o, c_null_ptr, clean, rebin, ridger%ptr)
    if (rc /= PRESSRIDGE_OK) then
       call finish(rc, where, ierr)
       return
    end if
    rc = c_ridger_tracers(ridger%ptr, nt, 0_c_int64_t, c_null_ptr, c_null_ptr, c_null_ptr, &
         c_null_ptr)
    ridger%ncat = ncat
    ridger%ntrcr = int(nt)
    if (present(ntrcr)) ntrcr = int(nt)
    len = nt
    pd = c_null_ptr
    pb = c_null_ptr
    pn = c_null_ptr
    ps = c_null_ptr
    if (present(trcr_depend)) then
       pd = c_loc(trcr_depend)
       len = size(trcr_depend, kind=c_int64_t)
    end if
    if (present(trcr_base)) then
       pb = c_loc(trcr_base)
       len = size(trcr_base, 1, kind=c_int64_t)
    end if
    if (present(n_trcr_strata)) then
       pn = c_loc(n_trcr_strata)
       len = size(n_trcr_strata, kind=c_int64_t)
    end if
    if (present(nt_strata)) then
       ps = c_loc(nt_strata)
       len = size(nt_strata, 1, kind=c_int64_t)
    end if
    if (present(trcr_depend)) then
       if (present(trcr_base)) then
          if (size(trcr_base, 1) /= size(trcr_depend)) len = -1
       end if
    end if
    if (present(nt_strata) .and. present(n_trcr_strata)) then
       if (size(nt_strata, 1) /= size(n_trcr_strata)) len = -1
    end if
    rc = PRESSRIDGE_OK
    if (len < 0) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'the tracer arrays must have the same first size', &
            where, ierr)
       return
    end if
    if (c_associated(pd) .or. c_associated(pb) .or. c_associated(pn) .or. c_associated(ps)) &
         rc = c_ridger_tracers(ridger%ptr, nt, len, pd, pb, pn, ps)
    call finish(rc, where, ierr)
  end subroutine pressridge_ridger_init

  !> Releases a ridging set-up.
  subroutine pressridge_ridger_free(ridger)
    type(pressridge_ridger), intent(inout) :: ridger
    integer(c_int32_t) :: rc
    rc = c_ridger_free(ridger%ptr)
    ridger%ptr = c_null_ptr
  end subroutine pressridge_ridger_free

  !> One ridging step of one cell, Icepack's icepack_step_ridge (snow, tracers, fluxes, the
  !> clean-up), with its argument names and units; the tracer layout comes from `ridger`.
  !> closing absent: closing and opening from rdg_conv and rdg_shear (CICE), hin_max(ncat)
  !> set to params%big; closing present: the host's rates closing and opening (SIS2).
  !> fresh, fsalt, fhocn, fpond are added to; the other diagnostics are overwritten;
  !> first_ice is set .true. for categories emptied by the clean-up.
  subroutine pressridge_step_ridge(ridger, dt, ndtd, hin_max, rdg_conv, rdg_shear, aicen, &
       trcrn, vicen, vsnon, aice0, dardg1dt, dardg2dt, dvirdgdt, opening, fpond, fresh, &
       fhocn, aparticn, krdgn, aredistn, vredistn, dardg1ndt, dardg2ndt, dvirdgndt, araftn, &
       vraftn, aice, fsalt, first_ice, closing, Tf, dpnd_ridge, ierr)
    type(pressridge_ridger), intent(in) :: ridger
    real(c_double), intent(in) :: dt                     !< dynamics time step (s)
    integer, intent(in) :: ndtd                          !< dynamics subcycles
    real(c_double), intent(inout), contiguous, target :: hin_max(0:) !< bounds (m)
    real(c_double), intent(in) :: rdg_conv, rdg_shear    !< 1/s
    real(c_double), intent(inout), contiguous, target :: aicen(:), vicen(:), vsnon(:)
    real(c_double), intent(inout), contiguous, target :: trcrn(:, :) !< (ntrcr, ncat)
    real(c_double), intent(inout), target :: aice0, aice
    real(c_double), intent(out), optional :: dardg1dt, dardg2dt, dvirdgdt
    real(c_double), intent(inout), target :: opening     !< 1/s
    real(c_double), intent(inout) :: fpond, fresh, fhocn, fsalt
    real(c_double), intent(out), optional, contiguous, target :: aparticn(:), krdgn(:), &
         aredistn(:), vredistn(:), dardg1ndt(:), dardg2ndt(:), dvirdgndt(:), araftn(:), vraftn(:)
    logical, intent(inout), optional :: first_ice(:)
    real(c_double), intent(in), optional, target :: closing
    real(c_double), intent(in) :: Tf                     !< freezing temperature (degC)
    real(c_double), intent(out), optional :: dpnd_ridge  !< m
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_step_ridge'
    type(c_fluxes) :: fl
    type(c_step_diag) :: d
    type(c_cat_diag) :: cd
    integer(c_int32_t), target :: zapped(size(aicen))
    type(c_ptr) :: pc
    integer(c_int32_t) :: rc
    integer :: n
    n = ridger%ncat
    if (size(aicen) /= n .or. size(vicen) /= n .or. size(vsnon) /= n .or. &
         size(hin_max) /= n + 1 .or. size(trcrn, 1) /= ridger%ntrcr .or. size(trcrn, 2) /= n) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'need aicen, vicen, vsnon(ncat), hin_max(0:ncat), &
            &trcrn(ntrcr, ncat) of the ridger''s sizes', where, ierr)
       return
    end if
    fl = c_fluxes(fresh, fsalt, fhocn, fpond, 0.0_c_double)
    zapped = 0
    if (present(aparticn)) cd%aparticn = c_loc(aparticn)
    if (present(krdgn)) cd%krdgn = c_loc(krdgn)
    if (present(aredistn)) cd%aredistn = c_loc(aredistn)
    if (present(vredistn)) cd%vredistn = c_loc(vredistn)
    if (present(dardg1ndt)) cd%dardg1ndt = c_loc(dardg1ndt)
    if (present(dardg2ndt)) cd%dardg2ndt = c_loc(dardg2ndt)
    if (present(dvirdgndt)) cd%dvirdgndt = c_loc(dvirdgndt)
    if (present(araftn)) cd%araftn = c_loc(araftn)
    if (present(vraftn)) cd%vraftn = c_loc(vraftn)
    cd%first_ice = c_loc(zapped)
    pc = c_null_ptr
    if (present(closing)) pc = c_loc(closing)
    rc = c_ridge_cell(ridger%ptr, dt, int(ndtd, c_int32_t), c_loc(hin_max), rdg_conv, &
         rdg_shear, pc, c_loc(opening), c_loc(aicen), c_loc(trcrn), c_loc(vicen), &
         c_loc(vsnon), c_loc(aice0), c_loc(aice), Tf, fl, d, cd)
    if (rc == PRESSRIDGE_OK) then
       fresh = fl%fresh
       fsalt = fl%fsalt
       fhocn = fl%fhocn
       fpond = fl%fpond
       if (present(dpnd_ridge)) dpnd_ridge = fl%dpnd_ridge
       if (present(dardg1dt)) dardg1dt = d%dardg1dt
       if (present(dardg2dt)) dardg2dt = d%dardg2dt
       if (present(dvirdgdt)) dvirdgdt = d%dvirdgdt
       if (present(first_ice)) first_ice = first_ice .or. zapped /= 0
    end if
    call finish(rc, where, ierr)
  end subroutine pressridge_step_ridge

  !> The ridging step of ncol cells in one call: aicen, vicen, vsnon(ncat, ncol),
  !> trcrn(ntrcr, ncat, ncol), aice0, aice(ncol), rdg_conv, rdg_shear(ncol); optional Tf(ncol)
  !> (default -1.8), fluxes fresh, fsalt, fhocn, fpond(ncol) (added to), rates dardg1dt,
  !> dardg2dt, dvirdgdt(ncol), and closing with opening (ncol, SIS2 convention; opening is
  !> also returned in the CICE convention). hin_max(0:ncat) is not modified.
  subroutine pressridge_step_ridge_cells(ridger, dt, ndtd, hin_max, rdg_conv, rdg_shear, &
       aicen, trcrn, vicen, vsnon, aice0, aice, Tf, fresh, fsalt, fhocn, fpond, dardg1dt, &
       dardg2dt, dvirdgdt, closing, opening, ierr)
    type(pressridge_ridger), intent(in) :: ridger
    real(c_double), intent(in) :: dt
    integer, intent(in) :: ndtd
    real(c_double), intent(in), contiguous, target :: hin_max(0:), rdg_conv(:), rdg_shear(:)
    real(c_double), intent(inout), contiguous, target :: aicen(:, :), vicen(:, :), &
         vsnon(:, :), trcrn(:, :, :), aice0(:), aice(:)
    real(c_double), intent(in), optional, contiguous, target :: Tf(:), closing(:)
    real(c_double), intent(inout), optional, contiguous, target :: fresh(:), fsalt(:), &
         fhocn(:), fpond(:), opening(:)
    real(c_double), intent(out), optional, contiguous, target :: dardg1dt(:), dardg2dt(:), &
         dvirdgdt(:)
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_step_ridge_cells'
    type(c_cell_arrays) :: c
    integer :: n, ncol
    n = ridger%ncat
    ncol = size(aicen, 2)
    if (size(aicen, 1) /= n .or. any(shape(vicen) /= [n, ncol]) .or. &
         any(shape(vsnon) /= [n, ncol]) .or. any(shape(trcrn) /= [ridger%ntrcr, n, ncol]) .or. &
         size(aice0) /= ncol .or. size(aice) /= ncol .or. size(rdg_conv) /= ncol .or. &
         size(rdg_shear) /= ncol .or. size(hin_max) /= n + 1) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'shapes: aicen, vicen, vsnon(ncat, ncol), &
            &trcrn(ntrcr, ncat, ncol), aice0, aice, rdg_conv, rdg_shear(ncol), hin_max(0:ncat)', &
            where, ierr)
       return
    end if
    c%rdg_conv = c_loc(rdg_conv)
    c%rdg_shear = c_loc(rdg_shear)
    if (present(closing)) c%closing = c_loc(closing)
    if (present(opening)) c%opening = c_loc(opening)
    if (present(Tf)) c%tf = c_loc(Tf)
    if (present(fresh)) c%fresh = c_loc(fresh)
    if (present(fsalt)) c%fsalt = c_loc(fsalt)
    if (present(fhocn)) c%fhocn = c_loc(fhocn)
    if (present(fpond)) c%fpond = c_loc(fpond)
    if (present(dardg1dt)) c%dardg1dt = c_loc(dardg1dt)
    if (present(dardg2dt)) c%dardg2dt = c_loc(dardg2dt)
    if (present(dvirdgdt)) c%dvirdgdt = c_loc(dvirdgdt)
    call finish(c_ridge_cells(ridger%ptr, int(ncol, c_int64_t), dt, int(ndtd, c_int32_t), &
         c_loc(hin_max), c_loc(aicen), c_loc(trcrn), c_loc(vicen), c_loc(vsnon), c_loc(aice0), &
         c_loc(aice), c), where, ierr)
  end subroutine pressridge_step_ridge_cells

end module pressridge
