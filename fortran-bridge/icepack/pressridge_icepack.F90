!> pressridge_icepack: Icepack's ridging step and ice strength with Icepack's own argument
!> lists, for a host that swaps pressridge in by its `use` line alone:
!>
!>   use pressridge_icepack, only: icepack_step_ridge => pressridge_icepack_step_ridge, &
!>        icepack_ice_strength => pressridge_icepack_ice_strength
!>
!> Compiled with the host beside Icepack (it uses icepack_intfc): the first call reads
!> Icepack's tracer flags and sizes and the ridging parameters (krdg_partic, krdg_redist,
!> mu_rdg, kstrength, Cf, Pstar, Cstar, the densities and thermodynamic constants) through
!> Icepack's own queries and makes the pressridge set-up for them (one per number of
!> categories and tracers and docleanup/dorebin, kept for the run; OpenMP threads share it).
!> Later calls use it without asking Icepack again (the queries would cost more than a
!> strength); a host that changes Icepack's parameters or tracer flags during the run calls
!> pressridge_icepack_refresh() after the change. The host's tracer tables
!> (trcr_depend, trcr_base, n_trcr_strata, nt_strata) carry each tracer, as Icepack takes
!> them; the roles of the tracers (which is an enthalpy, a pond, an aerosol...) come from
!> Icepack's flags: every pond scheme, the snow tracers with Icepack's refills, floe size,
!> isotopes, aerosols, brine. Errors, and biogeochemical tracers, which
!> pressridge does not carry yet, are reported as Icepack reports its own:
!> icepack_warnings_add and icepack_warnings_setabort.
!>
!> The simulator's tables instead of Icepack's constants, without a line more in the host: a
!> file `pressridge_in` in the run directory, read once at the first call, whose namelist
!>
!>   &pressridge_nml
!>     cf_table = 'data/ridging_table.nc'      ! C_f(h) of the strength, in place of Cf
!>     mu_rdg_table = 'data/ridging_table.nc'  ! mu_rdg(h) of the redistribution (m^0.5)
!>     friction = 1.0, friction_water = 0.6    ! the table's friction pair (1)
!>   /
!>
!> names either table or both ('' or absent: Icepack's Cf and mu_rdg). A host may instead call
!> pressridge_icepack_configure(path) before its first step. Without the file the drop-in is
!> Icepack, bit for bit.
module pressridge_icepack
  use, intrinsic :: iso_c_binding, only: c_associated, c_double, c_int32_t
  use, intrinsic :: iso_fortran_env, only: int64
  use pressridge
  use icepack_intfc, only: icepack_query_tracer_flags, icepack_query_tracer_sizes, &
       icepack_query_tracer_indices, icepack_query_parameters, icepack_max_nbtrcr
  ! Icepack's own error reporting (module icepack_warnings; icepack_intfc does not re-export
  ! these two).
  use icepack_warnings, only: icepack_warnings_add, icepack_warnings_setabort
  implicit none
  private

  public :: pressridge_icepack_step_ridge, pressridge_icepack_ice_strength, &
       pressridge_icepack_refresh, pressridge_icepack_configure

  !> One set-up: the values it was made for and its handle.
  type :: setup
     integer :: ncat = -1, ntrcr = -1, nilyr = -1, nslyr = -1, n_aero = -1, n_iso = -1
     integer :: nfsd = -1, kp = -1, kr = -1
     ! Biogeochemistry: PRESSRIDGE_BGC_*, tracers after ntrcr_o, nblyr, bio_index(1:nbtrcr).
     integer :: bgc_kind = 0, bgc_ntrcr = 0, nblyr = 0, nbtrcr = 0
     integer, allocatable :: bio_index(:)
     real(c_double) :: sk_l = 0
     real(c_double) :: mu_rdg = -1, refill(3) = 0
     !> tr_iage, tr_FY, tr_lvl, tr_pond_lvl, tr_snow, tr_pond_topo, tr_pond_sealvl, tr_brine
     logical :: flags(8) = .false., cleanup = .true., rebin = .true.
     type(pressridge_step_params) :: step
     type(pressridge_ridger) :: ridger
  end type setup

  integer, parameter :: max_setups = 16
  type(setup), save :: setups(max_setups)
  integer, save :: nsetups = 0
  !> Set-ups made since the last refresh: their indices are taken without asking Icepack.
  logical, save :: current(max_setups) = .false.
  !> The strength's options read from Icepack, and whether they are current.
  type(pressridge_options), save :: strength_options
  logical, save :: strength_current = .false.
  !> Whether the namelist file has been read (or found absent).
  logical, save :: configured = .false.
  !> Whether the last reading of a namelist file succeeded (or there was none).
  logical, save :: config_ok = .true.
  !> The tables of the namelist, kept open for the run.
  type(pressridge_cf_table), save :: nml_cf_table
  type(pressridge_mu_rdg_table), save :: nml_mu_rdg_table

contains

  !> Reads the namelist group pressridge_nml of file `path` (above) and sets the drop-in's
  !> tables from it: C_f(h) of the strength and mu_rdg(h) of the redistribution, at the
  !> friction pair it names. Call it outside OpenMP regions, before the first step, or let
  !> the first call read `pressridge_in` of the run directory. A file that cannot be read, an
  !> unknown name in it or a table that cannot be opened is reported through Icepack's
  !> warnings and aborts, naming the file.
  subroutine pressridge_icepack_configure(path)
    character(len=*), intent(in) :: path
    character(len=1024) :: cf_table, mu_rdg_table
    real(c_double) :: friction, friction_water
    type(pressridge_options) :: o
    type(pressridge_cf_table) :: cf_new
    type(pressridge_mu_rdg_table) :: mu_new
    integer :: u, ios, e
    character(len=512) :: iom
    character(len=:), allocatable :: msg
    character(len=*), parameter :: subname = '(pressridge_icepack_configure)'
    namelist /pressridge_nml/ cf_table, mu_rdg_table, friction, friction_water
    configured = .true.
    config_ok = .false.
    current = .false.
    strength_current = .false.
    cf_table = ''
    mu_rdg_table = ''
    friction = 1.0_c_double
    friction_water = 0.6_c_double
    open (newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=iom)
    if (ios == 0) then
       read (u, nml=pressridge_nml, iostat=ios, iomsg=iom)
       close (u)
    end if
    if (ios /= 0) then
       call abort_with(subname//' '//path//': '//trim(iom))
       return
    end if
    ! The file says the whole choice: a table it does not name is Icepack's constant.
    call pressridge_get_parameters(o)
    o%cf_source = PRESSRIDGE_CF_SOURCE_CONSTANT
    if (o%redistribution == PRESSRIDGE_REDISTRIBUTION_TABLE) &
         o%redistribution = PRESSRIDGE_REDISTRIBUTION_EXPONENTIAL
    if (len_trim(cf_table) > 0) then
       call pressridge_cf_table_open_at_friction(trim(cf_table), friction, friction_water, &
            cf_new, e)
       if (e /= PRESSRIDGE_OK) then
          call abort_with(subname//' '//path//', cf_table: '//trim(pressridge_last_error_message()))
          return
       end if
       call pressridge_options_set_cf_table(o, cf_new)
    end if
    if (len_trim(mu_rdg_table) > 0) then
       call pressridge_mu_rdg_table_open(trim(mu_rdg_table), friction, friction_water, &
            mu_new, e)
       if (e /= PRESSRIDGE_OK) then
          if (c_associated(cf_new%ptr)) call pressridge_cf_table_free(cf_new)
          call abort_with(subname//' '//path//', mu_rdg_table: '// &
               trim(pressridge_last_error_message()))
          return
       end if
       call pressridge_options_set_mu_rdg_table(o, mu_new)
    end if
    call pressridge_init_parameters(options=o)
    ! The options no longer name an earlier call's tables: release them (a host that
    ! configures again, or a test, leaks nothing).
    if (c_associated(nml_cf_table%ptr)) call pressridge_cf_table_free(nml_cf_table)
    if (c_associated(nml_mu_rdg_table%ptr)) call pressridge_mu_rdg_table_free(nml_mu_rdg_table)
    nml_cf_table = cf_new
    nml_mu_rdg_table = mu_new
    config_ok = .true.
    if (len_trim(cf_table) > 0) then
       msg = 'C_f from '//trim(cf_table)
    else
       msg = 'C_f from Icepack''s Cf'
    end if
    if (len_trim(mu_rdg_table) > 0) then
       msg = msg//', mu_rdg from '//trim(mu_rdg_table)
    else
       msg = msg//', mu_rdg from Icepack''s mu_rdg'
    end if
    write (*, '(a, f4.2, a, f4.2)') 'pressridge_icepack: '//path//': '//msg//' at mu = ', &
         friction, ', mu_w = ', friction_water
  end subroutine pressridge_icepack_configure

  !> Reads `pressridge_in` of the run directory at the first call, if the host has not called
  !> pressridge_icepack_configure (the caller holds the set-up's critical section);
  !> whether no error was reported.
  logical function configure_once() result(ok)
    logical :: there
    if (.not. configured) then
       configured = .true.
       inquire (file='pressridge_in', exist=there)
       if (there) call pressridge_icepack_configure('pressridge_in')
    end if
    ok = config_ok
  end function configure_once

  !> Makes the next call read Icepack's tracer flags, sizes and parameters again: for a host
  !> that changes them during the run (call it outside OpenMP regions).
  subroutine pressridge_icepack_refresh()
    current = .false.
    strength_current = .false.
  end subroutine pressridge_icepack_refresh

  !> Icepack's icepack_step_ridge (argument names, meanings and optional arguments as in
  !> Icepack 1.5): the complete ridging step of one cell by pressridge, biogeochemical
  !> tracers (skl_bgc or z_tracers) and their flux_bio included.
  subroutine pressridge_icepack_step_ridge(dt, ndtd, hin_max, rdg_conv, rdg_shear, aicen, &
       trcrn, vicen, vsnon, aice0, trcr_depend, trcr_base, n_trcr_strata, nt_strata, &
       dardg1dt, dardg2dt, dvirdgdt, opening, fpond, fresh, fhocn, faero_ocn, fiso_ocn, &
       aparticn, krdgn, aredistn, vredistn, dardg1ndt, dardg2ndt, dvirdgndt, araftn, vraftn, &
       aice, fsalt, first_ice, flux_bio, closing, Tf, dpnd_ridge, docleanup, dorebin)
    real(c_double), intent(in) :: dt, Tf
    integer, intent(in) :: ndtd
    real(c_double), intent(inout), contiguous :: hin_max(0:)
    integer, intent(in) :: trcr_depend(:), n_trcr_strata(:)
    real(c_double), intent(in) :: trcr_base(:, :)
    integer, intent(in) :: nt_strata(:, :)
    real(c_double), intent(inout) :: aice, aice0, rdg_conv, rdg_shear, dardg1dt, dardg2dt, &
         dvirdgdt, opening, fpond, fresh, fsalt, fhocn
    real(c_double), intent(inout), optional :: closing
    real(c_double), intent(inout), contiguous :: aicen(:), vicen(:), vsnon(:)
    real(c_double), intent(inout) :: dardg1ndt(:), dardg2ndt(:), dvirdgndt(:), aparticn(:), &
         krdgn(:), araftn(:), vraftn(:), aredistn(:), vredistn(:), faero_ocn(:), flux_bio(:)
    real(c_double), intent(inout), optional :: fiso_ocn(:)
    real(c_double), intent(inout), contiguous :: trcrn(:, :)
    logical, intent(inout) :: first_ice(:)
    real(c_double), intent(inout), optional :: dpnd_ridge
    logical, intent(in), optional :: docleanup, dorebin
    character(len=*), parameter :: subname = '(pressridge_icepack_step_ridge)'
    logical :: clean, rebin
    integer :: k, e
    real(c_double) :: fa(6), fi(3)
    clean = .true.
    rebin = .true.
    if (present(docleanup)) clean = docleanup
    if (present(dorebin)) rebin = dorebin
    ! A current set-up for these sizes and clean-up flags, else Icepack is asked.
    do k = 1, nsetups
       if (current(k) .and. setups(k)%ncat == size(aicen) .and. &
            setups(k)%ntrcr == size(trcrn, 1) .and. (setups(k)%cleanup .eqv. clean) .and. &
            (setups(k)%rebin .eqv. rebin)) exit
    end do
    if (k > nsetups) then
       k = setup_for(size(aicen), size(trcrn, 1), clean, rebin, trcr_depend, trcr_base, &
            n_trcr_strata, nt_strata)
       if (k == 0) return
    end if
    fa = 0
    fi = 0
    associate (s => setups(k))
      fa(1:s%n_aero) = faero_ocn(1:s%n_aero)
      if (present(fiso_ocn)) fi(1:s%n_iso) = fiso_ocn(1:s%n_iso)
      if (size(flux_bio) < s%nbtrcr) then
         call abort_with(subname//' flux_bio is shorter than nbtrcr')
         return
      end if
      call pressridge_step_ridge(s%ridger, dt, ndtd, hin_max, rdg_conv, rdg_shear, aicen, &
           trcrn, vicen, vsnon, aice0, dardg1dt, dardg2dt, dvirdgdt, opening, fpond, fresh, &
           fhocn, aparticn, krdgn, aredistn, vredistn, dardg1ndt, dardg2ndt, dvirdgndt, &
           araftn, vraftn, aice, fsalt, first_ice, closing, Tf, dpnd_ridge, &
           faero_ocn=fa(1:s%n_aero), fiso_ocn=fi(1:s%n_iso), &
           flux_bio=flux_bio(1:s%nbtrcr), ierr=e)
      if (e /= PRESSRIDGE_OK) then
         call abort_with(subname//' '//cell_message(pressridge_last_error_message()))
         return
      end if
      faero_ocn(1:s%n_aero) = fa(1:s%n_aero)
      if (present(fiso_ocn)) fiso_ocn(1:s%n_iso) = fi(1:s%n_iso)
    end associate
  end subroutine pressridge_icepack_step_ridge

  !> Icepack's icepack_ice_strength: the strength (N/m) of one cell by pressridge, with
  !> Icepack's kstrength, krdg_partic, krdg_redist, mu_rdg, Cf, Pstar, Cstar and densities.
  subroutine pressridge_icepack_ice_strength(aice, vice, aice0, aicen, vicen, strength)
    real(c_double), intent(in) :: aice, vice, aice0
    real(c_double), intent(in), contiguous :: aicen(:), vicen(:)
    real(c_double), intent(inout) :: strength
    type(pressridge_options) :: o
    integer :: e, kstrength, kp, kr
    logical :: ok
    ! The options read from Icepack once (under a critical section: OpenMP threads may call
    ! at once), then shared read-only: pressridge's defaults (or pressridge_in's tables) with
    ! Icepack's values.
    ok = .true.
    if (.not. strength_current) then
       !$omp critical (pressridge_icepack_setup)
       if (.not. strength_current) ok = configure_once()
       if (ok .and. .not. strength_current) then
          call pressridge_get_parameters(o)
          call icepack_query_parameters(kstrength_out=kstrength, krdg_partic_out=kp, &
               krdg_redist_out=kr, mu_rdg_out=o%params%mu_rdg, Cf_out=o%cf, &
               Pstar_out=o%params%pstar, Cstar_out=o%params%cstar, rhoi_out=o%params%rhoi, &
               rhow_out=o%params%rhow, gravit_out=o%params%gravit)
          o%strength_law = kstrength
          o%participation = kp
          ! A mu_rdg table set through pressridge_init_parameters(options=) is kept: Icepack's
          ! krdg_redist (0 or 1) cannot say it.
          if (o%redistribution /= PRESSRIDGE_REDISTRIBUTION_TABLE) o%redistribution = kr
          ! So is a C_f table (pressridge_in, or pressridge_init_parameters(cf_table=)).
          if (o%cf_source /= PRESSRIDGE_CF_SOURCE_TABLE) o%cf_source = PRESSRIDGE_CF_SOURCE_CONSTANT
          strength_options = o
          strength_current = .true.
       end if
       !$omp end critical (pressridge_icepack_setup)
    end if
    if (.not. ok) return
    call pressridge_ice_strength(aice, vice, aice0, aicen, vicen, strength, e, &
         strength_options)
    if (e /= PRESSRIDGE_OK) call abort_with('(pressridge_icepack_ice_strength) '// &
         cell_message(pressridge_last_error_message()))
  end subroutine pressridge_icepack_ice_strength

  !> The set-up for Icepack's present sizes, flags and parameters (made on first use), its
  !> index in `setups`; 0 after reporting an error to Icepack.
  integer function setup_for(ncat, ntrcr, clean, rebin, trcr_depend, trcr_base, &
       n_trcr_strata, nt_strata) result(k)
    integer, intent(in) :: ncat, ntrcr
    logical, intent(in) :: clean, rebin
    integer, intent(in) :: trcr_depend(:), n_trcr_strata(:), nt_strata(:, :)
    real(c_double), intent(in) :: trcr_base(:, :)
    type(setup) :: want
    logical :: iage, fy, lvl, pond_lvl, snow, pond_topo, pond_sealvl, brine, fsd, iso, aero
    integer :: nilyr, nslyr, nblyr, n_aero, n_iso, nbtrcr, nfsd, kp, kr, ntrcr_o, nt_fbri
    integer :: bio_index(icepack_max_nbtrcr)
    real(c_double) :: mu_rdg, rhos, rhoi, lfresh, cp_ice, sal, amin, mmin, hsmin, rhosnew, &
         rsnw_fall, sk_l
    logical :: snwgrain, skl_bgc, z_tracers
    character(len=32) :: saltflux, snwredist
    character(len=*), parameter :: subname = '(pressridge_icepack_step_ridge)'
    k = 0
    call icepack_query_tracer_sizes(nilyr_out=nilyr, nslyr_out=nslyr, nblyr_out=nblyr, &
         n_aero_out=n_aero, n_iso_out=n_iso, nbtrcr_out=nbtrcr, nfsd_out=nfsd, &
         ntrcr_o_out=ntrcr_o)
    call icepack_query_tracer_flags(tr_iage_out=iage, tr_FY_out=fy, tr_lvl_out=lvl, &
         tr_pond_lvl_out=pond_lvl, tr_pond_topo_out=pond_topo, &
         tr_pond_sealvl_out=pond_sealvl, tr_snow_out=snow, tr_brine_out=brine, &
         tr_fsd_out=fsd, tr_iso_out=iso, tr_aero_out=aero)
    call icepack_query_parameters(krdg_partic_out=kp, krdg_redist_out=kr, mu_rdg_out=mu_rdg, &
         rhos_out=rhos, rhoi_out=rhoi, Lfresh_out=lfresh, &
         cp_ice_out=cp_ice, ice_ref_salinity_out=sal, itd_area_min_out=amin, &
         itd_mass_min_out=mmin, hs_min_out=hsmin, saltflux_option_out=saltflux, &
         snwredist_out=snwredist, snwgrain_out=snwgrain, rhosnew_out=rhosnew, &
         rsnw_fall_out=rsnw_fall, skl_bgc_out=skl_bgc, z_tracers_out=z_tracers, sk_l_out=sk_l)
    ! Biogeochemistry: the tracers after ntrcr_o and the brine fraction, the bio tracers among
    ! them by bio_index. Icepack's column driver sets ntrcr_o before it adds fbri
    ! (icedrv_init_column.F90), which the layout of the flags counts with the physical
    ! tracers: the bio part starts after the later of the two.
    if (nbtrcr > 0) then
       if (skl_bgc) then
          want%bgc_kind = PRESSRIDGE_BGC_SKELETAL
          want%sk_l = sk_l
       else if (z_tracers) then
          want%bgc_kind = PRESSRIDGE_BGC_VERTICAL
          want%nblyr = nblyr
       else
          call abort_with(subname//' nbtrcr > 0 with neither skl_bgc nor z_tracers')
          return
       end if
       call icepack_query_tracer_indices(bio_index_out=bio_index, nt_fbri_out=nt_fbri)
       want%bgc_ntrcr = ntrcr - max(ntrcr_o, nt_fbri)
       want%nbtrcr = nbtrcr
       want%bio_index = bio_index(1:nbtrcr)
    else
       allocate(want%bio_index(0))
    end if
    if (.not. iso) n_iso = 0
    if (.not. aero) n_aero = 0
    if (.not. fsd) nfsd = 0
    want%ncat = ncat
    want%ntrcr = ntrcr
    want%nilyr = nilyr
    want%nslyr = nslyr
    want%n_aero = n_aero
    want%n_iso = n_iso
    want%kp = kp
    want%kr = kr
    want%mu_rdg = mu_rdg
    want%nfsd = nfsd
    want%flags = [iage, fy, lvl, pond_lvl, snow, pond_topo, pond_sealvl, brine]
    want%cleanup = clean
    want%rebin = rebin
    ! Icepack's refills of the snow tracers where there is no snow.
    if (snow .and. snwredist(1:3) == 'ITD') want%refill(1) = rhosnew
    if (snow .and. snwgrain) want%refill(2:3) = [rhos, rsnw_fall]
    call pressridge_default_step_params(want%step)
    want%step%rhos = rhos
    want%step%lfresh = lfresh
    want%step%cp_ice = cp_ice
    want%step%ice_ref_salinity = sal
    want%step%itd_area_min = amin
    want%step%itd_mass_min = mmin
    want%step%hs_min = hsmin
    want%step%salt_flux_prognostic = merge(1, 0, trim(saltflux) == 'prognostic')
    !$omp critical (pressridge_icepack_setup)
    do k = 1, nsetups
       if (same(setups(k), want)) exit
    end do
    if (k > nsetups) k = make(want, rhoi, trcr_depend, trcr_base, n_trcr_strata, nt_strata)
    if (k > 0) then
       ! The one current set-up for these sizes and flags.
       where (setups(1:nsetups)%ncat == ncat .and. setups(1:nsetups)%ntrcr == ntrcr .and. &
            (setups(1:nsetups)%cleanup .eqv. clean) .and. (setups(1:nsetups)%rebin .eqv. rebin)) &
            current(1:nsetups) = .false.
       current(k) = .true.
    end if
    !$omp end critical (pressridge_icepack_setup)
  end function setup_for

  !> Makes a set-up (the caller holds the critical section); its index, or 0 after an error.
  integer function make(want, rhoi, trcr_depend, trcr_base, n_trcr_strata, nt_strata) &
       result(k)
    type(setup), intent(in) :: want
    real(c_double), intent(in) :: rhoi
    integer, intent(in) :: trcr_depend(:), n_trcr_strata(:), nt_strata(:, :)
    real(c_double), intent(in) :: trcr_base(:, :)
    type(setup) :: s
    type(pressridge_options) :: o
    integer :: e, nt
    integer(c_int32_t), allocatable :: dep(:), nst(:), str(:, :)
    real(c_double), allocatable :: base(:, :)
    character(len=200) :: msg
    character(len=*), parameter :: subname = '(pressridge_icepack_step_ridge)'
    k = 0
    if (nsetups == max_setups) then
       call abort_with(subname//' more than 16 different ridging set-ups in one run')
       return
    end if
    if (.not. configure_once()) return
    s = want
    call pressridge_get_parameters(o)
    o%participation = want%kp
    if (o%redistribution /= PRESSRIDGE_REDISTRIBUTION_TABLE) o%redistribution = want%kr
    o%params%mu_rdg = want%mu_rdg
    o%params%rhoi = rhoi
    allocate(dep(want%ntrcr), nst(want%ntrcr), str(want%ntrcr, 2), base(want%ntrcr, 3))
    ! The host's tables, as Icepack takes them (their first ntrcr rows).
    if (size(trcr_depend) < want%ntrcr .or. size(n_trcr_strata) < want%ntrcr .or. &
         size(trcr_base, 1) < want%ntrcr .or. size(nt_strata, 1) < want%ntrcr .or. &
         size(trcr_base, 2) < 3 .or. size(nt_strata, 2) < 2) then
       write (msg, '(a, i0, a)') ' the tracer tables are shorter than trcrn''s ', &
            want%ntrcr, ' tracers'
       call abort_with(subname//trim(msg))
       return
    end if
    dep = int(trcr_depend(1:want%ntrcr), c_int32_t)
    base = trcr_base(1:want%ntrcr, 1:3)
    nst = int(n_trcr_strata(1:want%ntrcr), c_int32_t)
    str = int(nt_strata(1:want%ntrcr, 1:2), c_int32_t)
    call pressridge_ridger_init(s%ridger, want%ncat, want%nilyr, want%nslyr, want%flags(1), &
         want%flags(2), want%flags(3), want%flags(4), options=o, docleanup=want%cleanup, &
         dorebin=want%rebin, ntrcr=nt, host_trcr_depend=dep, host_trcr_base=base, &
         host_n_trcr_strata=nst, host_nt_strata=str, step_params=want%step, &
         tr_snow=want%flags(5), n_iso=want%n_iso, &
         n_aero=want%n_aero, tr_pond_topo=want%flags(6), tr_pond_sealvl=want%flags(7), &
         tr_brine=want%flags(8), nfsd=want%nfsd, rhos_empty=want%refill(1), &
         smice_empty=want%refill(2), rsnw_empty=want%refill(3), bgc_ntrcr=want%bgc_ntrcr, &
         skl_bgc=want%bgc_kind == PRESSRIDGE_BGC_SKELETAL, &
         z_tracers=want%bgc_kind == PRESSRIDGE_BGC_VERTICAL, nblyr=want%nblyr, &
         sk_l=want%sk_l, bio_index=want%bio_index, ierr=e)
    if (e /= PRESSRIDGE_OK) then
       call abort_with(subname//' '//trim(pressridge_last_error_message()))
       return
    end if
    nsetups = nsetups + 1
    setups(nsetups) = s
    k = nsetups
  end function make

  !> Whether two set-ups are for the same values (reals compared bit for bit).
  logical function same(a, b)
    type(setup), intent(in) :: a, b
    same = a%ncat == b%ncat .and. a%ntrcr == b%ntrcr .and. a%nilyr == b%nilyr .and. &
         a%nslyr == b%nslyr .and. a%n_aero == b%n_aero .and. a%n_iso == b%n_iso .and. &
         a%nfsd == b%nfsd .and. a%kp == b%kp .and. a%kr == b%kr .and. all(a%flags .eqv. b%flags) .and. &
         a%bgc_kind == b%bgc_kind .and. a%bgc_ntrcr == b%bgc_ntrcr .and. a%nblyr == b%nblyr .and. &
         a%nbtrcr == b%nbtrcr .and. bits(a%sk_l) == bits(b%sk_l) .and. &
         same_ints(a%bio_index, b%bio_index) .and. &
         (a%cleanup .eqv. b%cleanup) .and. (a%rebin .eqv. b%rebin) .and. &
         a%step%salt_flux_prognostic == b%step%salt_flux_prognostic .and. &
         all(bits(a%refill) == bits(b%refill)) .and. all(bits([a%mu_rdg, a%step%rhos, a%step%lfresh, a%step%cp_ice, &
         a%step%ice_ref_salinity, a%step%itd_area_min, a%step%itd_mass_min, a%step%hs_min]) == &
         bits([b%mu_rdg, b%step%rhos, b%step%lfresh, b%step%cp_ice, &
         b%step%ice_ref_salinity, b%step%itd_area_min, b%step%itd_mass_min, b%step%hs_min]))
  end function same

  !> Whether two integer arrays have the same size and values.
  logical function same_ints(a, b)
    integer, intent(in) :: a(:), b(:)
    same_ints = size(a) == size(b)
    if (same_ints) same_ints = all(a == b)
  end function same_ints

  elemental integer(int64) function bits(x)
    real(c_double), intent(in) :: x
    bits = transfer(x, 0_int64)
  end function bits

  !> The library's message about the one cell of a per-cell call, without the column index it
  !> gives that call's one-column grid ("column 0: ..., column index 0 counts from 0: Fortran
  !> column 1"), which is not the host's cell: like Icepack's own, the message names the
  !> variable, the category and the value, and the host's abort names the routine.
  function cell_message(msg) result(m)
    character(len=*), intent(in) :: msg
    character(len=:), allocatable :: m
    integer :: k
    m = trim(msg)
    if (index(m, 'column 0: ') == 1) m = m(11:)
    k = index(m, ' (column index 0 counts from 0')
    if (k > 0) m = m(:k - 1)
  end function cell_message

  !> Reports an error as Icepack reports its own.
  subroutine abort_with(msg)
    character(len=*), intent(in) :: msg
    call icepack_warnings_add(msg)
    call icepack_warnings_setabort(.true., __FILE__, __LINE__)
  end subroutine abort_with

end module pressridge_icepack
