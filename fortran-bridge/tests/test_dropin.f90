!> The Icepack drop-in (icepack/pressridge_icepack.F90) built against the stand-in of
!> Icepack's interface (icepack_stub.F90), without Icepack: with Icepack's argument lists it
!> gives pressridge_step_ridge's and pressridge_ice_strength's answers bit for bit, follows
!> a change of Icepack's parameters after pressridge_icepack_refresh, carries vertically
!> resolved bio tracers and their flux_bio, and reports what it refuses through Icepack's
!> warnings. (The drop-in against Icepack itself, every tracer group included:
!> bench/icepack/reference/check-dropin.sh.)
program test_dropin
  use, intrinsic :: iso_c_binding, only: c_double
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
  use pressridge
  use pressridge_icepack, only: icepack_step_ridge => pressridge_icepack_step_ridge, &
       icepack_ice_strength => pressridge_icepack_ice_strength, pressridge_icepack_refresh, &
       icepack_configure => pressridge_icepack_configure
  use icepack_intfc, only: stub_flags, stub_sizes, stub_krdg_redist, stub_mu_rdg, &
       stub_ntrcr_o, stub_nt_fbri, stub_z_tracers, stub_bio_index
  use icepack_warnings, only: stub_aborted, stub_message
  implicit none
  integer, parameter :: nc = 5
  integer :: failures = 0, nt, i, k, e, pass
  type(pressridge_ridger) :: rg
  integer :: dep(64), nst(64), str(64, 2)
  real(c_double) :: base(64, 3), hb(0:nc), h1(0:nc), h2(0:nc)
  real(c_double), allocatable :: t1(:, :), t2(:, :), t3(:, :), t4(:, :)
  real(c_double) :: fbio1(2), fbio2(29)
  integer :: nto
  real(c_double) :: a1(nc), v1(nc), s1(nc), a2(nc), v2(nc), s2(nc), x0(nc), a01, a02, ai1, &
       ai2, fa1(2), fa2(2), fi1(1), fi2(1), fb(1), d(3, 2), op(2), fp(2), fr(2), fh(2), fs(2), &
       p1, p2, cat(nc, 9, 2), conv, shear
  logical :: first1(nc), first2(nc)

  ! Icepack's layout: the CICE tracers, snow tracers, one isotope, two aerosol species.
  stub_flags = [.true., .true., .true., .true., .false., .false., .true., .false., .false., &
       .true., .true.]
  stub_sizes(4:5) = [2, 1]
  call pressridge_ridger_init(rg, nc, 7, 1, .true., .true., .true., .true., ntrcr=nt, &
       trcr_depend=dep, trcr_base=base, n_trcr_strata=nst, nt_strata=str, tr_snow=.true., &
       n_iso=1, n_aero=2, ierr=e)
  call check('explicit ridger: 37 tracers', e == PRESSRIDGE_OK .and. nt == 37)
  allocate(t1(nt, nc), t2(nt, nc))
  conv = 2.0e-6_c_double
  shear = 1.0e-6_c_double
  hb = [0.0_c_double, 0.6_c_double, 1.4_c_double, 2.4_c_double, 3.6_c_double, 5.0_c_double]
  do k = 1, nc
     a1(k) = 0.18_c_double
     v1(k) = a1(k) * (0.3_c_double + 0.9_c_double * (k - 1))
     s1(k) = 0.1_c_double * v1(k)
     t1(1:23, k) = [-15.0_c_double, (-3.0e8_c_double - 1.0e6_c_double * i, i = 1, 7), &
          -1.15e8_c_double, (4.0_c_double + 0.2_c_double * i, i = 1, 7), 2.0e7_c_double, &
          0.4_c_double, 0.8_c_double, 0.8_c_double, 0.2_c_double, 0.1_c_double, 0.01_c_double]
     t1(24:, k) = [(1.0e-3_c_double * (i + k), i = 24, nt)]
  end do
  do pass = 1, 2
     ! pass 2: Icepack's parameters changed between calls (uniform redistribution, mu_rdg).
     if (pass == 2) then
        stub_krdg_redist = 0
        stub_mu_rdg = 4.0_c_double
        call pressridge_icepack_refresh()
        call pressridge_ridger_free(rg)
        call pressridge_init_parameters(krdg_redist=0, mu_rdg=4.0_c_double)
        call pressridge_ridger_init(rg, nc, 7, 1, .true., .true., .true., .true., &
             tr_snow=.true., n_iso=1, n_aero=2, ierr=e)
        call pressridge_init_parameters(krdg_redist=1, mu_rdg=3.0_c_double)
     end if
     t2 = t1
     call second_copy()
     call pressridge_step_ridge(rg, 3600.0_c_double, 1, h1, 2.0e-6_c_double, 1.0e-6_c_double, &
          a1, t1, v1, s1, a01, d(1, 1), d(2, 1), d(3, 1), op(1), fp(1), fr(1), fh(1), &
          cat(:, 1, 1), cat(:, 2, 1), cat(:, 3, 1), cat(:, 4, 1), cat(:, 5, 1), cat(:, 6, 1), &
          cat(:, 7, 1), cat(:, 8, 1), cat(:, 9, 1), ai1, fs(1), first1, Tf=-1.8_c_double, &
          faero_ocn=fa1, fiso_ocn=fi1, ierr=e)
     call check('explicit call steps the cell', e == PRESSRIDGE_OK)
     call icepack_step_ridge(dt=3600.0_c_double, ndtd=1, hin_max=h2, rdg_conv=conv, &
          rdg_shear=shear, aicen=a2, trcrn=t2, vicen=v2, vsnon=s2, aice0=a02, &
          trcr_depend=dep(1:nt), trcr_base=base(1:nt, :), n_trcr_strata=nst(1:nt), &
          nt_strata=str(1:nt, :), dardg1dt=d(1, 2), dardg2dt=d(2, 2), dvirdgdt=d(3, 2), &
          opening=op(2), fpond=fp(2), fresh=fr(2), fhocn=fh(2), faero_ocn=fa2, fiso_ocn=fi2, &
          aparticn=cat(:, 1, 2), krdgn=cat(:, 2, 2), aredistn=cat(:, 3, 2), &
          vredistn=cat(:, 4, 2), dardg1ndt=cat(:, 5, 2), dardg2ndt=cat(:, 6, 2), &
          dvirdgndt=cat(:, 7, 2), araftn=cat(:, 8, 2), vraftn=cat(:, 9, 2), aice=ai2, &
          fsalt=fs(2), first_ice=first2, flux_bio=fb, Tf=-1.8_c_double)
     call check('drop-in with Icepack''s arguments = explicit call, bit for bit', &
          .not. stub_aborted .and. all(a1 == a2) .and. all(v1 == v2) .and. all(s1 == s2) .and. &
          all(t1 == t2) .and. a01 == a02 .and. ai1 == ai2 .and. all(h1 == h2) .and. &
          all(d(:, 1) == d(:, 2)) .and. op(1) == op(2) .and. fr(1) == fr(2) .and. &
          fh(1) == fh(2) .and. fs(1) == fs(2) .and. fp(1) == fp(2) .and. all(fa1 == fa2) .and. &
          all(fi1 == fi2) .and. all(cat(:, :, 1) == cat(:, :, 2)) .and. &
          (first1(1) .eqv. first2(1)) .and. all(fa1 > 0) .and. fi1(1) > 0)
  end do
  call pressridge_ridger_free(rg)
  stub_krdg_redist = 1
  stub_mu_rdg = 3.0_c_double
  call pressridge_icepack_refresh()
  ! The strength, Icepack-style, with Icepack's (stub) parameters.
  call pressridge_ice_strength(sum(a1), sum(v1), a01, a1, v1, p1, e)
  p2 = 0
  call icepack_ice_strength(sum(a1), sum(v1), a01, a1, v1, p2)
  call check('strength drop-in = pressridge_ice_strength (CICE defaults)', &
       e == PRESSRIDGE_OK .and. p1 == p2 .and. p1 > 0 .and. .not. stub_aborted)
  ! A mu_rdg table given through pressridge_init_parameters(options=) is kept by the drop-in:
  ! one value, 2 m^0.5, gives the strength of mu_rdg = 2.
  block
    type(pressridge_mu_rdg_table) :: mt
    type(pressridge_options) :: ot
    real(c_double) :: p3
    call pressridge_mu_rdg_table_new([1.0e-3_c_double, 1.0e3_c_double], &
         [2.0_c_double, 2.0_c_double], mt, e)
    call pressridge_default_options(ot)
    call pressridge_options_set_mu_rdg_table(ot, mt)
    call pressridge_init_parameters(options=ot)
    call pressridge_icepack_refresh()
    p2 = 0
    call icepack_ice_strength(sum(a1), sum(v1), a01, a1, v1, p2)
    stub_mu_rdg = 2.0_c_double
    call pressridge_default_options(ot)
    call pressridge_init_parameters(options=ot)
    call pressridge_icepack_refresh()
    p3 = 0
    call icepack_ice_strength(sum(a1), sum(v1), a01, a1, v1, p3)
    call check('strength drop-in keeps a mu_rdg table (one value = that mu_rdg)', &
         e == PRESSRIDGE_OK .and. p2 == p3 .and. p2 /= p1 .and. .not. stub_aborted)
    stub_mu_rdg = 3.0_c_double
    call pressridge_default_options(ot)
    call pressridge_init_parameters(options=ot)
    call pressridge_icepack_refresh()
    call pressridge_mu_rdg_table_free(mt)
  end block
  ! The simulator's tables through a namelist file (pressridge_in's group): the strength
  ! with C_f(h) of the shipped table at mu = 0.8, mu_w = 0.3 equals pressridge_ice_strength
  ! with that table, and differs from Icepack's constant Cf; a table that cannot be opened
  ! and an unknown name abort through Icepack's warnings, naming the file.
  block
    type(pressridge_cf_table) :: ct
    type(pressridge_options) :: ot
    character(len=1024) :: table, dir
    real(c_double) :: p3
    call get_command_argument(1, table)
    call get_command_argument(2, dir)
    call write_nml(trim(dir)//'/pressridge_in_good', "cf_table = '"//trim(table)// &
         "', friction = 0.8, friction_water = 0.3")
    call icepack_configure(trim(dir)//'/pressridge_in_good')
    p2 = 0
    call icepack_ice_strength(sum(a1), sum(v1), a01, a1, v1, p2)
    call pressridge_cf_table_open_at_friction(trim(table), 0.8_c_double, 0.3_c_double, ct, e)
    call pressridge_default_options(ot)
    call pressridge_options_set_cf_table(ot, ct)
    call pressridge_ice_strength(sum(a1), sum(v1), a01, a1, v1, p3, e, ot)
    call check('namelist C_f table: strength = pressridge_ice_strength with the table', &
         e == PRESSRIDGE_OK .and. p2 == p3 .and. p2 /= p1 .and. .not. stub_aborted)
    call pressridge_cf_table_free(ct)
    ! Configured again: the second call's tables replace the first's, which it releases
    ! (valgrind --leak-check=full finds none of the drop-in's memory lost).
    call icepack_configure(trim(dir)//'/pressridge_in_good')
    p2 = 0
    call icepack_ice_strength(sum(a1), sum(v1), a01, a1, v1, p2)
    call check('namelist read twice: the same strength, the first tables released', &
         p2 == p3 .and. .not. stub_aborted)
    call write_nml(trim(dir)//'/pressridge_in_missing', "cf_table = '"//trim(dir)// &
         "/no_such_table.nc'")
    call icepack_configure(trim(dir)//'/pressridge_in_missing')
    call check('namelist naming a missing table: an abort naming the file and the table', &
         stub_aborted .and. index(stub_message, 'pressridge_in_missing, cf_table') > 0 .and. &
         index(stub_message, 'no_such_table.nc') > 0)
    stub_aborted = .false.
    call write_nml(trim(dir)//'/pressridge_in_typo', "cf_tabel = 'x.nc'")
    call icepack_configure(trim(dir)//'/pressridge_in_typo')
    call check('namelist with an unknown name: an abort naming the file', &
         stub_aborted .and. index(stub_message, 'pressridge_in_typo') > 0)
    stub_aborted = .false.
    p2 = -1
    call icepack_ice_strength(sum(a1), sum(v1), a01, a1, v1, p2)
    call check('after a refused namelist: no strength computed', p2 == -1)
    call write_nml(trim(dir)//'/pressridge_in_none', "friction = 0.8")
    call icepack_configure(trim(dir)//'/pressridge_in_none')
    p2 = 0
    call icepack_ice_strength(sum(a1), sum(v1), a01, a1, v1, p2)
    call check('a namelist naming no table: Icepack''s constant Cf again', &
         p2 == p1 .and. .not. stub_aborted)
  end block
  ! Biogeochemistry: the same layout with the brine fraction and two vertically resolved bio
  ! tracers (z_tracers, nblyr = 1: 4 tracers each) after Icepack's ntrcr_o tracers.
  stub_flags(8) = .true.
  call pressridge_ridger_init(rg, nc, 7, 1, .true., .true., .true., .true., ntrcr=nto, &
       tr_snow=.true., n_iso=1, n_aero=2, tr_brine=.true., ierr=e)
  call pressridge_ridger_free(rg)
  call pressridge_ridger_init(rg, nc, 7, 1, .true., .true., .true., .true., ntrcr=nt, &
       trcr_depend=dep, trcr_base=base, n_trcr_strata=nst, nt_strata=str, tr_snow=.true., &
       n_iso=1, n_aero=2, tr_brine=.true., bgc_ntrcr=8, z_tracers=.true., nblyr=1, &
       bio_index=[nto + 1, nto + 5], ierr=e)
  call check('explicit ridger with vertical bio tracers: 38 + 8 tracers', &
       e == PRESSRIDGE_OK .and. nto == 38 .and. nt == 46)
  stub_sizes(6) = 2
  ! As Icepack's column driver: ntrcr_o is set before the brine fraction is added, so fbri
  ! (tracer 38) lies after it (icedrv_init_column.F90).
  stub_ntrcr_o = nto - 1
  stub_nt_fbri = nto
  stub_z_tracers = .true.
  stub_bio_index(1:2) = [nto + 1, nto + 5]
  call pressridge_icepack_refresh()
  allocate(t3(nt, nc), t4(nt, nc))
  do k = 1, nc
     t3(1:37, k) = t1(1:37, k)
     t3(38, k) = 1.0_c_double
     t3(39:, k) = [(0.5_c_double + 0.1_c_double * (i + k), i = 39, nt)]
  end do
  t4 = t3
  a1 = [(0.18_c_double, k = 1, nc)]
  v1 = [(a1(k) * (0.3_c_double + 0.9_c_double * (k - 1)), k = 1, nc)]
  s1 = 0.1_c_double * v1
  call second_copy()
  fbio1 = 0
  fbio2 = 0
  call pressridge_step_ridge(rg, 3600.0_c_double, 1, h1, conv, shear, a1, t3, v1, s1, a01, &
       d(1, 1), d(2, 1), d(3, 1), op(1), fp(1), fr(1), fh(1), aice=ai1, fsalt=fs(1), &
       first_ice=first1, Tf=-1.8_c_double, faero_ocn=fa1, flux_bio=fbio1, ierr=e)
  call check('explicit call with bio tracers steps the cell', e == PRESSRIDGE_OK)
  call icepack_step_ridge(dt=3600.0_c_double, ndtd=1, hin_max=h2, rdg_conv=conv, &
       rdg_shear=shear, aicen=a2, trcrn=t4, vicen=v2, vsnon=s2, aice0=a02, &
       trcr_depend=dep(1:nt), trcr_base=base(1:nt, :), n_trcr_strata=nst(1:nt), &
       nt_strata=str(1:nt, :), dardg1dt=d(1, 2), dardg2dt=d(2, 2), dvirdgdt=d(3, 2), &
       opening=op(2), fpond=fp(2), fresh=fr(2), fhocn=fh(2), faero_ocn=fa2, &
       aparticn=x0, krdgn=x0, aredistn=x0, vredistn=x0, dardg1ndt=x0, dardg2ndt=x0, &
       dvirdgndt=x0, araftn=x0, vraftn=x0, aice=ai2, fsalt=fs(2), first_ice=first2, &
       flux_bio=fbio2, Tf=-1.8_c_double)
  call check('drop-in with bio tracers = explicit call, flux_bio included, bit for bit', &
       .not. stub_aborted .and. all(a1 == a2) .and. all(v1 == v2) .and. all(s1 == s2) .and. &
       all(t3 == t4) .and. a01 == a02 .and. fr(1) == fr(2) .and. fs(1) == fs(2) .and. &
       all(fbio1 == fbio2(1:2)) .and. all(fbio2(3:) == 0) .and. all(fbio1 > 0))
  call pressridge_ridger_free(rg)
  stub_flags(8) = .false.
  stub_ntrcr_o = 0
  stub_nt_fbri = 0
  stub_bio_index = 0
  ! Back to the 37-tracer layout (its tables are the first 37 rows of these).
  nt = size(t2, 1)

  ! What it refuses, through Icepack's warnings.
  stub_z_tracers = .false.
  call pressridge_icepack_refresh()
  call refused_call(.true.)
  call check('bio tracers of no known kind (nbtrcr > 0, neither skl_bgc nor z_tracers): an &
       &abort through Icepack''s warnings naming them', &
       stub_aborted .and. index(stub_message, 'skl_bgc') > 0)
  stub_sizes(6) = 0
  call pressridge_icepack_refresh()
  stub_aborted = .false.
  k = dep(24)
  dep(24) = -1
  call refused_call(.false.)
  call check('host tables with a trcr_depend of no base and no tracer: an abort naming the tracer', &
       stub_aborted .and. index(stub_message, 'tracer 24') > 0)
  dep(24) = k

  ! Bad states as a host's loop over its cells meets them (CICE's step_dyn_ridge calls every
  ! cell and asks icepack_warnings_aborted once, after the loop): a good cell, the bad one,
  ! the good cell again. The bad cell is refused through Icepack's warnings naming the
  ! variable and category and left as it was; the good cells after it get the answer of a
  ! cell stepped alone, bit for bit.
  call bad_cell('NaN area', 2, ieee_value(0.0_c_double, ieee_quiet_nan), 0.0_c_double, &
       'aicen[category 1] is not finite')
  call bad_cell('negative area', 2, -0.1_c_double, 0.0_c_double, &
       'aicen[category 1] is negative')
  call bad_cell('NaN volume', 3, 0.18_c_double, ieee_value(0.0_c_double, ieee_quiet_nan), &
       'vicen[category 2] is not finite')
  ! A volume without area is a state Icepack's step repairs, not refuses: here the ridged ice
  ! gives the category a little area, so that its thickness is far above its bounds and the
  ! clean-up's rebin moves it whole into the thickest category (without ridging,
  ! zap_small_areas would put it into the ocean). No abort; its neighbours are untouched.
  call bad_cell('volume without area', 4, 0.0_c_double, 0.5_c_double, '')
  if (failures > 0) then
     print '(i0, a)', failures, ' drop-in checks failed'
     error stop 1
  end if
  print '(a)', 'drop-in (Icepack stand-in): all checks passed'

contains

  !> The column's second copy (a2, v2, s2 of a1, v1, s1; the tracers are the caller's), its
  !> open water and area, the bounds, and every output zeroed.
  subroutine second_copy()
    a2 = a1
    v2 = v1
    s2 = s1
    a01 = 1 - sum(a1)
    a02 = a01
    ai1 = sum(a1)
    ai2 = ai1
    h1 = hb
    h2 = hb
    fa1 = 0
    fa2 = 0
    fi1 = 0
    fi2 = 0
    d = 0
    op = 0
    fp = 0
    fr = 0
    fh = 0
    fs = 0
    first1 = .false.
    first2 = .false.
    cat = 0
    x0 = 0
  end subroutine second_copy

  !> The drop-in with Icepack's arguments on the second copy of the column (a call it is
  !> expected to refuse).
  subroutine refused_call(cleanup)
    logical, intent(in) :: cleanup
    call icepack_step_ridge(dt=3600.0_c_double, ndtd=1, hin_max=h2, rdg_conv=conv, &
         rdg_shear=shear, aicen=a2, trcrn=t2, vicen=v2, vsnon=s2, aice0=a02, &
         trcr_depend=dep(1:nt), trcr_base=base(1:nt, :), n_trcr_strata=nst(1:nt), &
         nt_strata=str(1:nt, :), dardg1dt=d(1, 2), dardg2dt=d(2, 2), dvirdgdt=d(3, 2), &
         opening=op(2), fpond=fp(2), fresh=fr(2), fhocn=fh(2), faero_ocn=fa2, &
         aparticn=x0, krdgn=x0, aredistn=x0, vredistn=x0, dardg1ndt=x0, dardg2ndt=x0, &
         dvirdgndt=x0, araftn=x0, vraftn=x0, aice=ai2, fsalt=fs(2), first_ice=first2, &
         flux_bio=fb, Tf=-1.8_c_double, docleanup=cleanup)
  end subroutine refused_call

  !> The host's loop over three cells, the second with category k's area set to ak and, where
  !> vk is not 0, its volume to vk (the cell's open water keeps the area at 1); `refusal` is
  !> what the warning must say ('' for a state the step accepts).
  subroutine bad_cell(what, k, ak, vk, refusal)
    character(len=*), intent(in) :: what, refusal
    integer, intent(in) :: k
    real(c_double), intent(in) :: ak, vk
    real(c_double) :: a(nc, 3), v(nc, 3), s(nc, 3), t(nt, nc, 3), a0(3), ai(3), fr3(3), bad(nc)
    real(c_double) :: ref_a(nc), ref_v(nc), ref_s(nc), ref_t(nt, nc), ref_a0, ref_ai, ref_fr
    integer :: c
    logical :: untouched
    do c = 1, 3
       a(:, c) = a1
       v(:, c) = v1
       s(:, c) = s1
       t(:, :, c) = t1(1:nt, :)
    end do
    a(k, 2) = ak
    if (vk /= 0) v(k, 2) = vk
    bad = a(:, 2)
    a0 = 1 - sum(a1)
    a0(2) = max(1 - sum(a(:, 2)), 0.0_c_double)
    if (ieee_is_nan(ak)) a0(2) = 1 - sum(a1)
    ai = sum(a1)
    ! The good cell stepped alone.
    ref_a = a1
    ref_v = v1
    ref_t = t1(1:nt, :)
    ref_s = s1
    ref_a0 = 1 - sum(a1)
    ref_ai = sum(a1)
    call cell_step(ref_a, ref_v, ref_s, ref_t, ref_a0, ref_ai, ref_fr)
    stub_aborted = .false.
    stub_message = ''
    do c = 1, 3
       call cell_step(a(:, c), v(:, c), s(:, c), t(:, :, c), a0(c), ai(c), fr3(c))
    end do
    if (refusal == '') then
       call check('host loop, '//what//': no abort, the category moved whole by the &
            &clean-up''s rebin (the ridged ice gave it area), the volume kept in the cell, the &
            &cells beside it as if stepped alone', &
            .not. stub_aborted .and. v(k, 2) == 0 .and. a(k, 2) == 0 .and. &
            abs(sum(v(:, 2)) - sum(v1) - vk + v1(k)) < 1e-12_c_double * sum(v1) &
            .and. all(a(:, 3) == ref_a) .and. all(v(:, 3) == ref_v) .and. a0(3) == ref_a0 &
            .and. all(t(:, :, 3) == ref_t) .and. fr3(3) == ref_fr)
    else
       untouched = all(a(:, 2) == bad .or. (ieee_is_nan(a(:, 2)) .and. ieee_is_nan(bad)))
       call check('host loop, '//what//': an abort through Icepack''s warnings naming it ('// &
            refusal//', no one-cell grid''s column index), the bad cell left as it was, the &
            &next cell as if stepped alone', &
            stub_aborted .and. index(stub_message, refusal) > 0 .and. &
            index(stub_message, 'column') == 0 .and. untouched .and. &
            all(a(:, 1) == ref_a) .and. all(a(:, 3) == ref_a) .and. all(v(:, 3) == ref_v) &
            .and. a0(3) == ref_a0 .and. all(t(:, :, 3) == ref_t) .and. fr3(3) == ref_fr)
    end if
    stub_aborted = .false.
  end subroutine bad_cell

  !> One cell through the drop-in with Icepack's arguments (the 37-tracer layout), fluxes from
  !> zero; fresh its fresh-water flux.
  subroutine cell_step(a, v, s, t, a0, ai, fresh)
    real(c_double), intent(inout) :: a(nc), v(nc), s(nc), t(nt, nc), a0, ai
    real(c_double), intent(out) :: fresh
    real(c_double) :: h(0:nc), dd(3), o, fpd, fh3, fs3, fa(2), fi(1), fb3(1)
    logical :: fi_(nc)
    h = hb
    fresh = 0
    fpd = 0
    fh3 = 0
    fs3 = 0
    fa = 0
    fi = 0
    fi_ = .false.
    call icepack_step_ridge(dt=3600.0_c_double, ndtd=1, hin_max=h, rdg_conv=conv, &
         rdg_shear=shear, aicen=a, trcrn=t, vicen=v, vsnon=s, aice0=a0, &
         trcr_depend=dep(1:nt), trcr_base=base(1:nt, :), n_trcr_strata=nst(1:nt), &
         nt_strata=str(1:nt, :), dardg1dt=dd(1), dardg2dt=dd(2), dvirdgdt=dd(3), &
         opening=o, fpond=fpd, fresh=fresh, fhocn=fh3, faero_ocn=fa, fiso_ocn=fi, &
         aparticn=x0, krdgn=x0, aredistn=x0, vredistn=x0, dardg1ndt=x0, dardg2ndt=x0, &
         dvirdgndt=x0, araftn=x0, vraftn=x0, aice=ai, fsalt=fs3, first_ice=fi_, &
         flux_bio=fb3, Tf=-1.8_c_double)
  end subroutine cell_step

  !> Writes a namelist file of one pressridge_nml group holding `body`.
  subroutine write_nml(path, body)
    character(len=*), intent(in) :: path, body
    integer :: u
    open (newunit=u, file=path, status='replace', action='write')
    write (u, '(a)') '&pressridge_nml', '  '//body, '/'
    close (u)
  end subroutine write_nml

  subroutine check(what, ok)
    character(len=*), intent(in) :: what
    logical, intent(in) :: ok
    if (ok) then
       print '(a, a)', 'ok     ', what
    else
       print '(a, a)', 'FAIL   ', what
       failures = failures + 1
    end if
  end subroutine check

end program test_dropin
