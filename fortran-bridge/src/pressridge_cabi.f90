!> pressridge_cabi_mod: the C ABI as Fortran sees it (include/pressridge.h), and nothing else.
!>
!> Owns the status codes, option codes, tracer flags and C_f presets; the bind(C) types
!> pressridge_params and pressridge_options (the C structs PressridgeParams and
!> PressridgeOptions, with CICE's defaults as initial values: tests/params_faces.rs checks
!> pressridge_params against the Rust ItdParams::FIELDS); the opaque handles
!> (pressridge_cf_table, pressridge_ridge_table, pressridge_run, pressridge_ridger); the
!> bind(C) structs the wrappers fill (c_grid, c_rates, c_tracers, c_fluxes, c_step_diag, c_cat_diag,
!> c_cell_arrays); and the bind(C) interfaces c_* of every C function the wrappers call.
!> No executable code. Hosts `use pressridge`, which re-exports the public names; the c_*
!> names are for the other modules of the bridge (src/pressridge_*.f90).
module pressridge_cabi_mod
  use, intrinsic :: iso_c_binding
  implicit none
  public

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
  integer, parameter, public :: PRESSRIDGE_ABI_VERSION = 3

  ! Option codes: the values of CICE's krdg_partic, krdg_redist and kstrength.
  integer(c_int32_t), parameter, public :: PRESSRIDGE_PARTICIPATION_THORNDIKE = 0
  integer(c_int32_t), parameter, public :: PRESSRIDGE_PARTICIPATION_EXPONENTIAL = 1
  integer(c_int32_t), parameter, public :: PRESSRIDGE_REDISTRIBUTION_UNIFORM = 0
  integer(c_int32_t), parameter, public :: PRESSRIDGE_REDISTRIBUTION_EXPONENTIAL = 1
  !> Lipscomb's exponential with mu_rdg per category thickness from options%mu_rdg_table
  integer(c_int32_t), parameter, public :: PRESSRIDGE_REDISTRIBUTION_TABLE = 2
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
  integer(c_int32_t), parameter, public :: PRESSRIDGE_TRACER_SNOW = 16
  integer(c_int32_t), parameter, public :: PRESSRIDGE_TRACER_POND_TOPO = 32
  integer(c_int32_t), parameter, public :: PRESSRIDGE_TRACER_POND_SEALVL = 64
  integer(c_int32_t), parameter, public :: PRESSRIDGE_TRACER_BRINE = 128
  ! Biogeochemical tracers of the complete ridging step (Icepack skl_bgc, z_tracers).
  integer(c_int32_t), parameter, public :: PRESSRIDGE_BGC_NONE = 0
  integer(c_int32_t), parameter, public :: PRESSRIDGE_BGC_SKELETAL = 1
  integer(c_int32_t), parameter, public :: PRESSRIDGE_BGC_VERTICAL = 2

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
     !> mu_rdg table (PRESSRIDGE_REDISTRIBUTION_TABLE); set with pressridge_options_set_mu_rdg_table
     type(c_ptr) :: mu_rdg_table = c_null_ptr
     type(pressridge_params) :: params
  end type pressridge_options

  !> Thermodynamic constants and clean-up thresholds of the complete ridging step (the C
  !> PressridgeStepParams); the initial values are Icepack's, as
  !> pressridge_default_step_params gives them. Pass to pressridge_ridger_init(step_params=).
  type, bind(C), public :: pressridge_step_params
     real(c_double) :: rhos = 330.0_c_double                   !< snow density (kg/m^3)
     !> latent heat of melting of fresh ice (J/kg), Icepack's Lvap - Lsub difference
     real(c_double) :: lfresh = 2.835e6_c_double - 2.501e6_c_double
     real(c_double) :: cp_ice = 2106.0_c_double                !< specific heat of fresh ice (J/(kg K))
     real(c_double) :: fsnowrdg = 0.5_c_double                 !< snow on ridging ice kept on the ridge (1)
     real(c_double) :: ice_ref_salinity = 4.0_c_double         !< salinity of zapped ice (ppt)
     integer(c_int32_t) :: salt_flux_prognostic = 0            !< 1: saltflux_option = 'prognostic'
     real(c_double) :: itd_area_min = 1.0e-11_c_double         !< area below which ice is zapped (1)
     real(c_double) :: itd_mass_min = 1.0e-10_c_double         !< mass below which ice is zapped (kg/m^2)
     real(c_double) :: hs_min = 1.0e-4_c_double                !< snow checked above this thickness (m)
     real(c_double) :: tmin = -100.0_c_double                  !< lowest snow temperature (degC)
  end type pressridge_step_params

  !> A C_f table handle (free with pressridge_cf_table_free).
  type, public :: pressridge_cf_table
     type(c_ptr) :: ptr = c_null_ptr
  end type pressridge_cf_table

  !> A mu_rdg table handle (free with pressridge_mu_rdg_table_free).
  type, public :: pressridge_mu_rdg_table
     type(c_ptr) :: ptr = c_null_ptr
  end type pressridge_mu_rdg_table

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
     integer :: n_aero = 0 !< aerosol species
     integer :: n_iso = 0  !< water-isotope species
     integer :: nbtrcr = 0 !< biogeochemical tracers
  end type pressridge_ridger

  ! The C structs the wrappers fill; not re-exported by `pressridge`.

  !> PressridgeTracers.
  type, bind(C) :: c_tracers
     integer(c_int32_t) :: flags = 0, n_iso = 0, n_aero = 0, nfsd = 0
     real(c_double) :: rhos_empty = 0, smice_empty = 0, rsnw_empty = 0
     type(c_ptr) :: host_trcr_depend = c_null_ptr, host_trcr_base = c_null_ptr, &
          host_n_trcr_strata = c_null_ptr, host_nt_strata = c_null_ptr
     integer(c_int64_t) :: host_ntrcr = 0
     integer(c_int32_t) :: bgc_kind = 0, bgc_ntrcr = 0, nblyr = 0
     real(c_double) :: sk_l = 0
     integer(c_int32_t) :: nbtrcr = 0
     type(c_ptr) :: bio_index = c_null_ptr
  end type c_tracers

  !> PressridgeOceanFluxes.
  type, bind(C) :: c_fluxes
     real(c_double) :: fresh = 0, fsalt = 0, fhocn = 0, fpond = 0, dpnd_ridge = 0
     real(c_double) :: faero_ocn(6) = 0, fiso_ocn(3) = 0, flux_bio(29) = 0
  end type c_fluxes

  !> PressridgeStepDiagnostics.
  type, bind(C) :: c_step_diag
     real(c_double) :: closing = 0, opening = 0, dardg1dt = 0, dardg2dt = 0, dvirdgdt = 0, &
          ice_to_ocean = 0, snow_to_ocean = 0
     integer(c_int64_t) :: niter = 0
  end type c_step_diag

  !> PressridgeCategoryDiagnostics.
  type, bind(C) :: c_cat_diag
     type(c_ptr) :: dardg1ndt = c_null_ptr, dardg2ndt = c_null_ptr, dvirdgndt = c_null_ptr, &
          aparticn = c_null_ptr, krdgn = c_null_ptr, araftn = c_null_ptr, vraftn = c_null_ptr, &
          aredistn = c_null_ptr, vredistn = c_null_ptr, first_ice = c_null_ptr
  end type c_cat_diag

  !> PressridgeCellArrays.
  type, bind(C) :: c_cell_arrays
     type(c_ptr) :: rdg_conv = c_null_ptr, rdg_shear = c_null_ptr, closing = c_null_ptr, &
          opening = c_null_ptr, tf = c_null_ptr, valid = c_null_ptr, fresh = c_null_ptr, &
          fsalt = c_null_ptr, fhocn = c_null_ptr, fpond = c_null_ptr, dardg1dt = c_null_ptr, &
          dardg2dt = c_null_ptr, dvirdgdt = c_null_ptr, faero_ocn = c_null_ptr, &
          fiso_ocn = c_null_ptr, flux_bio = c_null_ptr
  end type c_cell_arrays

  !> PressridgeGrid: the layout of the per-category and per-column arrays.
  type, bind(C) :: c_grid
     integer(c_int64_t) :: ncat, ncol, cat_stride, col_stride, len, col_stride_1d, len_1d
  end type c_grid

  !> PressridgeRidgeRates: optional rate outputs of the ridging step (null: not wanted).
  type, bind(C) :: c_rates
     type(c_ptr) :: closing = c_null_ptr, opening = c_null_ptr, dardg1dt = c_null_ptr, &
          dardg2dt = c_null_ptr, dvirdgdt = c_null_ptr
  end type c_rates

  ! The C functions (include/pressridge.h), in the order errors and versions, options,
  ! strength, ridging step, complete step, C_f tables, ridging tables, simulator.
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
     integer(c_int32_t) function c_step_params_default(p) &
          bind(C, name="pressridge_step_params_default")
       import :: c_int32_t, pressridge_step_params
       type(pressridge_step_params), intent(out) :: p
     end function c_step_params_default
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
     integer(c_int32_t) function c_ridger_new(ncat, nilyr, nslyr, tracers, options, step, &
          cleanup, rebin, ridger) bind(C, name="pressridge_ridger_new")
       import :: c_int32_t, c_int64_t, c_ptr, c_tracers
       integer(c_int64_t), value :: ncat, nilyr, nslyr
       type(c_tracers), intent(in) :: tracers
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
     integer(c_int32_t) function c_mu_rdg_table_open(path, len, mu, mu_w, table) &
          bind(C, name="pressridge_mu_rdg_table_open")
       import :: c_int32_t, c_int64_t, c_char, c_double, c_ptr
       character(kind=c_char), intent(in) :: path(*)
       integer(c_int64_t), value :: len
       real(c_double), value :: mu, mu_w
       type(c_ptr), intent(out) :: table
     end function c_mu_rdg_table_open
     integer(c_int32_t) function c_mu_rdg_table_new(thickness, mu_rdg, n, table) &
          bind(C, name="pressridge_mu_rdg_table_new")
       import :: c_int32_t, c_int64_t, c_double, c_ptr
       real(c_double), intent(in) :: thickness(*), mu_rdg(*)
       integer(c_int64_t), value :: n
       type(c_ptr), intent(out) :: table
     end function c_mu_rdg_table_new
     integer(c_int32_t) function c_mu_rdg_table_lookup(table, h, mu_rdg, clamped) &
          bind(C, name="pressridge_mu_rdg_table_lookup")
       import :: c_int32_t, c_double, c_ptr
       type(c_ptr), value :: table
       real(c_double), value :: h
       real(c_double), intent(out) :: mu_rdg
       integer(c_int32_t), intent(out) :: clamped
     end function c_mu_rdg_table_lookup
     integer(c_int32_t) function c_mu_rdg_table_free(table) &
          bind(C, name="pressridge_mu_rdg_table_free")
       import :: c_int32_t, c_ptr
       type(c_ptr), value :: table
     end function c_mu_rdg_table_free
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

end module pressridge_cabi_mod
