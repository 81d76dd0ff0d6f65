!> pressridge_ridging_mod: the ridging step, as CICE/Icepack's ridge_ice and
!> icepack_step_ridge.
!>
!> Owns the area and volume step (no snow, tracers or fluxes): pressridge_ridge_ice (one
!> cell, Icepack-style, the options of pressridge_init_parameters) and the batched generic
!> pressridge_ridge_step, two thin rank-specific entry points, ridge_step_2d
!> (aicen(ncat, ncol), x(ncol)) and ridge_step_3d (CICE's block layout aicen(nx, ny, ncat),
!> x(nx, ny)), over one implementation, ridge_columns, which takes the caller's arrays as
!> array_arg describes them (shape and address; in place, no copies) and reads the layout
!> from the rank of aicen.
!> And the complete step with snow, tracers and ocean fluxes: the set-up pressridge_ridger
!> (pressridge_ridger_init, pressridge_ridger_free), one cell (pressridge_step_ridge,
!> Icepack's argument names and units) and ncol cells in one call
!> (pressridge_step_ridge_cells). Hosts `use pressridge`.
module pressridge_ridging_mod
  use, intrinsic :: iso_c_binding
  use pressridge_cabi_mod
  use pressridge_base_mod
  implicit none
  private

  public :: pressridge_ridge_step, pressridge_ridge_ice
  public :: pressridge_ridger_init, pressridge_ridger_free, pressridge_step_ridge
  public :: pressridge_step_ridge_cells

  !> Where pressridge_ridger_init points the library at a present but empty tracer array
  !> (never written: the library rejects the length first).
  real(c_double), target, save :: no_tracers = 0

  !> One ridging step of many columns in one call, in place; layouts as pressridge_strength.
  interface pressridge_ridge_step
     module procedure ridge_step_2d, ridge_step_3d
  end interface pressridge_ridge_step

contains

  ! ---------------------------------------------------------- area and volume step

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
         options_ptr(), r), where, ierr)
  end subroutine pressridge_ridge_ice

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
    call ridge_columns(arg_real2(aicen), arg_real2(vicen), arg_real1(aice0), &
         arg_real1(convergence), arg_real1(shear), dt, opt_real1(hin_max), options, &
         opt_mask1(valid), valid, opt_real1(closing), opt_real1(opening), opt_real1(dardg1dt), &
         opt_real1(dardg2dt), opt_real1(dvirdgdt), ierr)
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
    call ridge_columns(arg_real3(aicen), arg_real3(vicen), arg_real2(aice0), &
         arg_real2(convergence), arg_real2(shear), dt, opt_real1(hin_max), options, &
         opt_mask2(valid), valid, opt_real2(closing), opt_real2(opening), opt_real2(dardg1dt), &
         opt_real2(dardg2dt), opt_real2(dvirdgdt), ierr)
  end subroutine ridge_step_3d

  !> The batched ridging step in either layout (columns_of), on the arrays of ridge_step_2d
  !> or ridge_step_3d as array_arg describes them: shapes checked, then one call of the C ABI
  !> on the caller's memory; absent rates are not computed.
  subroutine ridge_columns(aicen, vicen, aice0, convergence, shear, dt, hin_max, options, &
       valid, mask, closing, opening, dardg1dt, dardg2dt, dvirdgdt, ierr)
    type(array_arg), intent(in) :: aicen, vicen, aice0, convergence, shear, hin_max
    real(c_double), intent(in) :: dt
    type(pressridge_options), intent(in), optional, target :: options
    type(array_arg), intent(in) :: valid
    logical, intent(in), optional :: mask(*)  !< valid's values
    type(array_arg), intent(in) :: closing, opening, dardg1dt, dardg2dt, dvirdgdt
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_ridge_step'
    type(columns) :: c
    integer(c_int32_t), allocatable, target :: flags(:)
    type(c_rates) :: r
    if (.not. columns_of(aicen, vicen, c, where, ierr)) return
    if (.not. fits(c, [aice0, convergence, shear, valid, closing, opening, dardg1dt, &
         dardg2dt, dvirdgdt], [character(len=11) :: 'aice0', 'convergence', 'shear', 'valid', &
         'closing', 'opening', 'dardg1dt', 'dardg2dt', 'dvirdgdt'], where, ierr)) return
    if (hin_max%present .and. hin_max%n == 0) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'hin_max is empty', where, ierr)
       return
    end if
    r = c_rates(closing=closing%ptr, opening=opening%ptr, dardg1dt=dardg1dt%ptr, &
         dardg2dt=dardg2dt%ptr, dvirdgdt=dvirdgdt%ptr)
    call finish(c_ridge_step(c%grid, aicen%ptr, vicen%ptr, aice0%ptr, hin_max%ptr, &
         int(hin_max%n, c_int64_t), convergence%ptr, shear%ptr, dt, mask_ptr(valid, mask, flags), &
         options_ptr(options), r), where, ierr)
  end subroutine ridge_columns

  ! ---------------------------------------------------------- the complete step (issue 15)

  !> Initialises a ridging set-up once: ncat categories, the CICE tracer layout with nilyr ice
  !> and nslyr snow layers and the optional tracers (Icepack's flags), the options (default:
  !> those of pressridge_init_parameters at this call, CICE's if it was never called;
  !> participation, redistribution and params are used) and Icepack's docleanup and
  !> dorebin (default .true.). Optionally returns the layout as Icepack's arrays (ntrcr and,
  !> of one first size, ntrcr or more, trcr_depend, trcr_base(:, 3), n_trcr_strata,
  !> nt_strata(:, 2)). step_params: the thermodynamic constants and clean-up thresholds
  !> (rhos, Lfresh, cp_ice, fsnowrdg, the salt flux option, ...; default: Icepack's).
  !> The other tracer groups, in the order of Icepack's driver (default: off): tr_snow
  !> (smice, smliq, rhos, rsnw), tr_pond_topo or tr_pond_sealvl (ponds on the ice area; one
  !> pond scheme at a time), nfsd floe-size categories, n_iso water-isotope (0-3) and n_aero
  !> aerosol (0-6) species, tr_brine (fbri); rhos_empty, smice_empty, rsnw_empty: the snow
  !> tracers where there is no snow (kg/m3, kg/m3, m; 0, or Icepack's refills rhosnew with
  !> snwredist = 'ITD', rhos and rsnw_fall with snwgrain). host_trcr_depend(ntrcr),
  !> host_trcr_base(ntrcr, 3), host_n_trcr_strata(ntrcr), host_nt_strata(ntrcr, 2): the host's
  !> own Icepack tracer tables (all four or none; ntrcr the layout's): each tracer is then
  !> carried as they say, as Icepack moves every tracer through them. Biogeochemistry
  !> (Icepack's tracers after ntrcr_o and fbri): bgc_ntrcr more tracers, of which
  !> bio_index(1:nbtrcr) (1-based tracer numbers, Icepack's) start the bio tracers, skeletal
  !> (skl_bgc, with sk_l in m) or vertically resolved (z_tracers, with nblyr; needs
  !> tr_brine); their fluxes to the ocean go to flux_bio of the step.
  subroutine pressridge_ridger_init(ridger, ncat, nilyr, nslyr, tr_iage, tr_FY, tr_lvl, &
       tr_pond_lvl, options, docleanup, dorebin, ntrcr, trcr_depend, trcr_base, &
       n_trcr_strata, nt_strata, step_params, tr_snow, n_iso, n_aero, tr_pond_topo, &
       tr_pond_sealvl, tr_brine, nfsd, rhos_empty, smice_empty, rsnw_empty, host_trcr_depend, &
       host_trcr_base, host_n_trcr_strata, host_nt_strata, bgc_ntrcr, skl_bgc, z_tracers, &
       nblyr, sk_l, bio_index, ierr)
    type(pressridge_ridger), intent(out) :: ridger
    integer, intent(in) :: ncat, nilyr, nslyr
    logical, intent(in) :: tr_iage, tr_FY, tr_lvl, tr_pond_lvl
    logical, intent(in), optional :: tr_snow, tr_pond_topo, tr_pond_sealvl, tr_brine
    integer, intent(in), optional :: n_iso, n_aero, nfsd
    real(c_double), intent(in), optional :: rhos_empty, smice_empty, rsnw_empty
    integer(c_int32_t), intent(in), optional, contiguous, target :: host_trcr_depend(:), &
         host_n_trcr_strata(:), host_nt_strata(:, :)
    real(c_double), intent(in), optional, contiguous, target :: host_trcr_base(:, :)
    integer, intent(in), optional :: bgc_ntrcr, nblyr
    logical, intent(in), optional :: skl_bgc, z_tracers
    real(c_double), intent(in), optional :: sk_l       !< m
    integer, intent(in), optional :: bio_index(:)
    type(pressridge_options), intent(in), optional, target :: options
    logical, intent(in), optional :: docleanup, dorebin
    type(pressridge_step_params), intent(in), optional, target :: step_params
    integer, intent(out), optional :: ntrcr
    integer(c_int32_t), intent(out), optional, contiguous, target :: trcr_depend(:), &
         n_trcr_strata(:), nt_strata(:, :)
    real(c_double), intent(out), optional, contiguous, target :: trcr_base(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_ridger_init'
    integer(c_int32_t) :: flags, clean, rebin, rc
    type(c_tracers) :: tr
    integer(c_int64_t) :: nt, len
    type(c_ptr) :: o, sp
    type(array_arg) :: arrays(4)
    integer(c_int32_t), allocatable, target :: bio(:)
    integer :: i
    flags = 0
    if (tr_iage) flags = flags + PRESSRIDGE_TRACER_AGE
    if (tr_FY) flags = flags + PRESSRIDGE_TRACER_FIRST_YEAR
    if (tr_lvl) flags = flags + PRESSRIDGE_TRACER_LEVEL_ICE
    if (tr_pond_lvl) flags = flags + PRESSRIDGE_TRACER_PONDS
    if (present(tr_snow)) then
       if (tr_snow) flags = flags + PRESSRIDGE_TRACER_SNOW
    end if
    if (present(tr_pond_topo)) then
       if (tr_pond_topo) flags = flags + PRESSRIDGE_TRACER_POND_TOPO
    end if
    if (present(tr_pond_sealvl)) then
       if (tr_pond_sealvl) flags = flags + PRESSRIDGE_TRACER_POND_SEALVL
    end if
    if (present(tr_brine)) then
       if (tr_brine) flags = flags + PRESSRIDGE_TRACER_BRINE
    end if
    tr%flags = flags
    if (present(n_iso)) tr%n_iso = int(n_iso, c_int32_t)
    if (present(n_aero)) tr%n_aero = int(n_aero, c_int32_t)
    if (present(nfsd)) tr%nfsd = int(nfsd, c_int32_t)
    if (present(rhos_empty)) tr%rhos_empty = rhos_empty
    if (present(smice_empty)) tr%smice_empty = smice_empty
    if (present(rsnw_empty)) tr%rsnw_empty = rsnw_empty
    if (present(host_trcr_depend) .and. present(host_trcr_base) .and. &
         present(host_n_trcr_strata) .and. present(host_nt_strata)) then
       if (size(host_trcr_base, 1) /= size(host_trcr_depend) .or. &
            size(host_trcr_base, 2) /= 3 .or. size(host_n_trcr_strata) /= size(host_trcr_depend) &
            .or. size(host_nt_strata, 1) /= size(host_trcr_depend) .or. &
            size(host_nt_strata, 2) /= 2) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'host tables: host_trcr_depend(ntrcr), &
               &host_trcr_base(ntrcr, 3), host_n_trcr_strata(ntrcr), host_nt_strata(ntrcr, 2)', &
               where, ierr)
          return
       end if
       tr%host_trcr_depend = c_loc(host_trcr_depend)
       tr%host_trcr_base = c_loc(host_trcr_base)
       tr%host_n_trcr_strata = c_loc(host_n_trcr_strata)
       tr%host_nt_strata = c_loc(host_nt_strata)
       tr%host_ntrcr = size(host_trcr_depend, kind=c_int64_t)
    else if (present(host_trcr_depend) .or. present(host_trcr_base) .or. &
         present(host_n_trcr_strata) .or. present(host_nt_strata)) then
       call fail(PRESSRIDGE_ERR_BAD_VALUE, 'host tables: give all four or none', where, ierr)
       return
    end if
    if (present(skl_bgc)) then
       if (skl_bgc) tr%bgc_kind = PRESSRIDGE_BGC_SKELETAL
    end if
    if (present(z_tracers)) then
       if (z_tracers) then
          if (tr%bgc_kind /= PRESSRIDGE_BGC_NONE) then
             call fail(PRESSRIDGE_ERR_BAD_VALUE, 'skl_bgc and z_tracers: one at a time', &
                  where, ierr)
             return
          end if
          tr%bgc_kind = PRESSRIDGE_BGC_VERTICAL
       end if
    end if
    if (tr%bgc_kind /= PRESSRIDGE_BGC_NONE) then
       if (.not. (present(bgc_ntrcr) .and. present(bio_index))) then
          call fail(PRESSRIDGE_ERR_BAD_VALUE, 'biogeochemical tracers need bgc_ntrcr and &
               &bio_index', where, ierr)
          return
       end if
       tr%bgc_ntrcr = int(bgc_ntrcr, c_int32_t)
       if (present(nblyr)) tr%nblyr = int(nblyr, c_int32_t)
       if (present(sk_l)) tr%sk_l = sk_l
       bio = int(bio_index, c_int32_t)
       tr%nbtrcr = size(bio, kind=c_int32_t)
       if (size(bio) > 0) tr%bio_index = c_loc(bio)
    end if
    clean = 1
    rebin = 1
    if (present(docleanup)) then
       if (.not. docleanup) clean = 0
    end if
    if (present(dorebin)) then
       if (.not. dorebin) rebin = 0
    end if
    o = options_ptr(options)
    sp = c_null_ptr
    if (present(step_params)) sp = c_loc(step_params)
    rc = c_ridger_new(int(ncat, c_int64_t), int(nilyr, c_int64_t), int(nslyr, c_int64_t), &
         tr, o, sp, clean, rebin, ridger%ptr)
    if (rc /= PRESSRIDGE_OK) then
       call finish(rc, where, ierr)
       return
    end if
    rc = c_ridger_tracers(ridger%ptr, nt, 0_c_int64_t, c_null_ptr, c_null_ptr, c_null_ptr, &
         c_null_ptr)
    ridger%ncat = ncat
    ridger%ntrcr = int(nt)
    ridger%n_iso = int(tr%n_iso)
    ridger%n_aero = int(tr%n_aero)
    ridger%nbtrcr = int(tr%nbtrcr)
    if (present(ntrcr)) ntrcr = int(nt)
    ! The tracer arrays, present ones passed on: all of the same first size, the length the C
    ! call is told (the library writes ntrcr rows), trcr_base with 3 columns, nt_strata with 2.
    arrays = [opt_int1(trcr_depend), opt_real2(trcr_base), opt_int1(n_trcr_strata), &
         opt_int2(nt_strata)]
    len = nt
    if (any(arrays%present)) len = maxval(arrays%shape(1), mask=arrays%present)
    do i = 1, size(arrays)
       if (.not. arrays(i)%present) cycle
       if (arrays(i)%shape(1) /= len) len = -1
       ! Present but empty: still passed (the library reports the length it is told).
       if (arrays(i)%n == 0) arrays(i)%ptr = c_loc(no_tracers)
    end do
    rc = PRESSRIDGE_OK
    if (len < 0) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'the tracer arrays must have the same first size', &
            where, ierr)
       return
    end if
    if (arrays(2)%present .and. arrays(2)%shape(2) /= 3) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'trcr_base must have 3 columns', where, ierr)
       return
    end if
    if (arrays(4)%present .and. arrays(4)%shape(2) /= 2) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'nt_strata must have 2 columns', where, ierr)
       return
    end if
    if (any(arrays%present)) rc = c_ridger_tracers(ridger%ptr, nt, len, arrays(1)%ptr, &
         arrays(2)%ptr, arrays(3)%ptr, arrays(4)%ptr)
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
  !> first_ice is set .true. for categories emptied by the clean-up. The optional
  !> per-category arrays (aparticn ... vraftn, first_ice) have ncat values each; faero_ocn
  !> and fiso_ocn (kg m-2 s-1, added to) at least the ridger's n_aero and n_iso values,
  !> flux_bio (mmol or kg m-2 s-1, added to) at least its nbtrcr.
  subroutine pressridge_step_ridge(ridger, dt, ndtd, hin_max, rdg_conv, rdg_shear, aicen, &
       trcrn, vicen, vsnon, aice0, dardg1dt, dardg2dt, dvirdgdt, opening, fpond, fresh, &
       fhocn, aparticn, krdgn, aredistn, vredistn, dardg1ndt, dardg2ndt, dvirdgndt, araftn, &
       vraftn, aice, fsalt, first_ice, closing, Tf, dpnd_ridge, faero_ocn, fiso_ocn, flux_bio, &
       ierr)
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
    real(c_double), intent(inout), optional :: faero_ocn(:), fiso_ocn(:) !< kg m-2 s-1
    real(c_double), intent(inout), optional :: flux_bio(:) !< mmol (kg) m-2 s-1
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
    ! The optional per-category arrays: ncat values each (the library writes ncat).
    if (.not. sized([opt_real1(aparticn), opt_real1(krdgn), opt_real1(aredistn), &
         opt_real1(vredistn), opt_real1(dardg1ndt), opt_real1(dardg2ndt), opt_real1(dvirdgndt), &
         opt_real1(araftn), opt_real1(vraftn), opt_mask1(first_ice)], [character(len=9) :: &
         'aparticn', 'krdgn', 'aredistn', 'vredistn', 'dardg1ndt', 'dardg2ndt', 'dvirdgndt', &
         'araftn', 'vraftn', 'first_ice'], n, 'ncat', where, ierr)) return
    if (present(faero_ocn)) then
       if (size(faero_ocn) < ridger%n_aero) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'faero_ocn needs n_aero values', where, ierr)
          return
       end if
    end if
    if (present(fiso_ocn)) then
       if (size(fiso_ocn) < ridger%n_iso) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'fiso_ocn needs n_iso values', where, ierr)
          return
       end if
    end if
    if (present(flux_bio)) then
       if (size(flux_bio) < ridger%nbtrcr) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'flux_bio needs nbtrcr values', where, ierr)
          return
       end if
    end if
    fl%fresh = fresh
    fl%fsalt = fsalt
    fl%fhocn = fhocn
    fl%fpond = fpond
    if (present(faero_ocn)) fl%faero_ocn(1:ridger%n_aero) = faero_ocn(1:ridger%n_aero)
    if (present(fiso_ocn)) fl%fiso_ocn(1:ridger%n_iso) = fiso_ocn(1:ridger%n_iso)
    if (present(flux_bio)) fl%flux_bio(1:ridger%nbtrcr) = flux_bio(1:ridger%nbtrcr)
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
       if (present(faero_ocn)) faero_ocn(1:ridger%n_aero) = fl%faero_ocn(1:ridger%n_aero)
       if (present(fiso_ocn)) fiso_ocn(1:ridger%n_iso) = fl%fiso_ocn(1:ridger%n_iso)
       if (present(flux_bio)) flux_bio(1:ridger%nbtrcr) = fl%flux_bio(1:ridger%nbtrcr)
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
  !> also returned in the CICE convention), each optional array of ncol values, and the
  !> aerosol, isotope and biogeochemical fluxes faero_ocn(n_aero, ncol), fiso_ocn(n_iso,
  !> ncol), flux_bio(nbtrcr, ncol) (added to). hin_max(0:ncat) is not modified.
  subroutine pressridge_step_ridge_cells(ridger, dt, ndtd, hin_max, rdg_conv, rdg_shear, &
       aicen, trcrn, vicen, vsnon, aice0, aice, Tf, fresh, fsalt, fhocn, fpond, dardg1dt, &
       dardg2dt, dvirdgdt, closing, opening, faero_ocn, fiso_ocn, flux_bio, ierr)
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
    real(c_double), intent(inout), optional, contiguous, target :: faero_ocn(:, :), &
         fiso_ocn(:, :), flux_bio(:, :)
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
    ! The optional per-column arrays: ncol values each (the library reads or writes ncol).
    if (.not. sized([opt_real1(Tf), opt_real1(fresh), opt_real1(fsalt), opt_real1(fhocn), &
         opt_real1(fpond), opt_real1(dardg1dt), opt_real1(dardg2dt), opt_real1(dvirdgdt), &
         opt_real1(closing), opt_real1(opening)], [character(len=8) :: 'Tf', 'fresh', 'fsalt', &
         'fhocn', 'fpond', 'dardg1dt', 'dardg2dt', 'dvirdgdt', 'closing', 'opening'], ncol, &
         'ncol', where, ierr)) return
    if (present(faero_ocn)) then
       if (any(shape(faero_ocn) /= [ridger%n_aero, ncol])) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'faero_ocn must be (n_aero, ncol)', where, ierr)
          return
       end if
       if (ridger%n_aero > 0) c%faero_ocn = c_loc(faero_ocn)
    end if
    if (present(fiso_ocn)) then
       if (any(shape(fiso_ocn) /= [ridger%n_iso, ncol])) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'fiso_ocn must be (n_iso, ncol)', where, ierr)
          return
       end if
       if (ridger%n_iso > 0) c%fiso_ocn = c_loc(fiso_ocn)
    end if
    if (present(flux_bio)) then
       if (any(shape(flux_bio) /= [ridger%nbtrcr, ncol])) then
          call fail(PRESSRIDGE_ERR_BAD_SIZE, 'flux_bio must be (nbtrcr, ncol)', where, ierr)
          return
       end if
       if (ridger%nbtrcr > 0) c%flux_bio = c_loc(flux_bio)
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

end module pressridge_ridging_mod
