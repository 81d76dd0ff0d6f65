!> Tests of the Fortran module `pressridge`: values agree with the Rust API (the files the
!> `pressridge` command line writes from data/sample_itd.nc) to round-off, in both array
!> layouts and through the Icepack-style per-cell calls; errors come back as ierr with a
!> message; tables and simulator runs work from Fortran.
!>
!> Usage: test_pressridge SAMPLE.nc REFDIR (REFDIR holds strength_*.nc, ridged.nc,
!> cf_table.nc and ridge_table.nc made by the Makefile).
program test_pressridge
  use, intrinsic :: iso_c_binding, only: c_double, c_int32_t
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use pressridge
  use sample_io
  implicit none

  character(len=1024) :: sample, dir
  integer :: ni, nj, ncat, ncol, i, j, e, passed = 0, failed = 0
  real(c_double), allocatable :: aicen(:, :, :), vicen(:, :, :), aice0(:, :), divu(:, :), &
       shear(:, :), conv(:, :), hin_max(:), p(:, :), pref(:, :), pcell(:, :), a2(:, :), &
       v2(:, :), p1(:), a0_1(:)
  type(pressridge_options) :: o, d
  type(pressridge_cf_table) :: cft, cft2
  type(pressridge_ridge_table) :: rt
  type(pressridge_run) :: run
  character(len=:), allocatable :: s
  real(c_double) :: x, y, z
  real(c_double), allocatable :: th(:), cf(:), vol(:)
  logical :: clamped, known
  integer :: ns, nh, nv, nf

  call get_command_argument(1, sample)
  call get_command_argument(2, dir)
  call read_grid(trim(sample), ni, nj, ncat)
  ncol = ni * nj
  allocate(aicen(ni, nj, ncat), vicen(ni, nj, ncat), aice0(ni, nj), divu(ni, nj), &
       shear(ni, nj), conv(ni, nj), hin_max(ncat + 1), p(ni, nj), pref(ni, nj), pcell(ni, nj))
  call read_3d(trim(sample), 'aicen', aicen)
  call read_3d(trim(sample), 'vicen', vicen)
  call read_2d(trim(sample), 'aice0', aice0)
  call read_2d(trim(sample), 'divu', divu)
  call read_2d(trim(sample), 'shear', shear)
  call read_1d(trim(sample), 'hin_max', hin_max)
  conv = max(-divu, 0.0_c_double)

  ! --- version, ABI, defaults
  s = pressridge_version()
  call check('version is not empty', len(s) > 0)
  call check('linked ABI version equals the module''s', &
       pressridge_linked_abi_version() == PRESSRIDGE_ABI_VERSION)
  call pressridge_default_options(d)
  call check('Fortran initial options equal the library defaults', same_options(o, d))

  ! --- strength, default options, CICE block layout, against `pressridge strength`
  call pressridge_strength(aicen, vicen, p, aice0=aice0, ierr=e)
  call check('strength (block layout) succeeds', e == PRESSRIDGE_OK)
  call read_2d(trim(dir)//'/strength_default.nc', 'strength', pref)
  call check('strength = pressridge strength (defaults)', agree(p, pref))

  ! The same through the Icepack-style call, cell by cell, as CICE would call it.
  do j = 1, nj
     do i = 1, ni
        pcell(i, j) = 0
        call pressridge_ice_strength(aice=sum(aicen(i, j, :)), vice=sum(vicen(i, j, :)), &
             aice0=aice0(i, j), aicen=aicen(i, j, :), vicen=vicen(i, j, :), &
             strength=pcell(i, j), ierr=e)
        if (e /= PRESSRIDGE_OK) exit
     end do
  end do
  call check('pressridge_ice_strength per cell succeeds', e == PRESSRIDGE_OK)
  call check('per-cell strength = batched strength (bit for bit)', all(pcell == p))

  ! Layout aicen(ncat, ncol).
  allocate(a2(ncat, ncol), v2(ncat, ncol), p1(ncol), a0_1(ncol))
  a2 = transpose(reshape(aicen, [ncol, ncat]))
  v2 = transpose(reshape(vicen, [ncol, ncat]))
  a0_1 = reshape(aice0, [ncol])
  call pressridge_strength(a2, v2, p1, aice0=a0_1, ierr=e)
  call check('strength (ncat, ncol) layout = block layout', &
       e == PRESSRIDGE_OK .and. all(p1 == reshape(p, [ncol])))
  ! Without aice0 (1 - sum(aicen)), within round-off of the given aice0.
  call pressridge_strength(a2, v2, p1, ierr=e)
  call check('strength without aice0 agrees to round-off', &
       e == PRESSRIDGE_OK .and. agree(reshape(p1, [ni, nj]), p, 1.0e-9_c_double))

  ! --- other options against the command line
  o%participation = PRESSRIDGE_PARTICIPATION_THORNDIKE
  o%redistribution = PRESSRIDGE_REDISTRIBUTION_UNIFORM
  call pressridge_strength(aicen, vicen, p, aice0=aice0, options=o, ierr=e)
  call read_2d(trim(dir)//'/strength_thorndike_uniform.nc', 'strength', pref)
  call check('Thorndike + uniform = pressridge strength', e == 0 .and. agree(p, pref))
  call pressridge_init_parameters(krdg_partic=0, krdg_redist=0)
  do j = 1, nj
     do i = 1, ni
        call pressridge_ice_strength(0.0_c_double, 0.0_c_double, aice0(i, j), aicen(i, j, :), &
             vicen(i, j, :), pcell(i, j))
     end do
  end do
  call check('pressridge_init_parameters(krdg_partic=0, krdg_redist=0) per cell', &
       all(pcell == p))
  call pressridge_init_parameters(options=d)

  o = d
  o%strength_law = PRESSRIDGE_STRENGTH_HIBLER1979
  call pressridge_strength(aicen, vicen, p, aice0=aice0, options=o, ierr=e)
  call read_2d(trim(dir)//'/strength_hibler.nc', 'strength', pref)
  call check('Hibler (1979) = pressridge strength --strength hibler', e == 0 .and. agree(p, pref))

  call pressridge_cf_table_open(trim(dir)//'/cf_table.nc', cft, e)
  call check('C_f table opens', e == PRESSRIDGE_OK)
  o = d
  call pressridge_options_set_cf_table(o, cft)
  call pressridge_strength(aicen, vicen, p, aice0=aice0, options=o, cf_clamped_columns=nf, ierr=e)
  call read_2d(trim(dir)//'/strength_cf_table.nc', 'strength', pref)
  call check('C_f table = pressridge strength --cf-table', e == 0 .and. agree(p, pref))
  call check('clamped columns are counted', nf >= 0 .and. nf <= ncol)
  call pressridge_cf_table_lookup(cft, 1.4_c_double, x, clamped)
  call check('C_f table lookup interpolates', abs(x - 13.5_c_double) < 1e-12 .and. .not. clamped)
  call pressridge_cf_table_lookup(cft, 9.0_c_double, x, clamped)
  call check('C_f table lookup clamps', x == 18.0_c_double .and. clamped)
  call pressridge_cf_table_nodes(cft, th, cf)
  call check('C_f table nodes', size(th) == 4 .and. th(4) == 4.0_c_double .and. cf(1) == 6.0_c_double)
  call pressridge_cf_table_new(th, cf, cft2, e)
  o = d
  call pressridge_options_set_cf_table(o, cft2)
  call pressridge_strength(aicen, vicen, pcell, aice0=aice0, options=o, ierr=e)
  call check('C_f table from nodes gives the same strength', e == 0 .and. all(pcell == p))
  call pressridge_cf_table_free(cft2)
  call pressridge_cf_table_free(cft)

  ! Redistribution with mu_rdg per category thickness from a table (issue 34): one value
  ! everywhere is that mu_rdg; a lookup beyond the nodes is flagged.
  block
    type(pressridge_mu_rdg_table) :: mt
    real(c_double) :: pflat(ni, nj), pmu(ni, nj)
    call pressridge_mu_rdg_table_new([1.0e-3_c_double, 1.0e3_c_double], &
         [2.0_c_double, 2.0_c_double], mt, e)
    call check('mu_rdg table from nodes', e == 0)
    o = d
    call pressridge_options_set_mu_rdg_table(o, mt)
    call pressridge_strength(aicen, vicen, pflat, aice0=aice0, options=o, ierr=e)
    o = d
    o%params%mu_rdg = 2.0_c_double
    call pressridge_strength(aicen, vicen, pmu, aice0=aice0, options=o, ierr=e)
    call check('mu_rdg table of one value = mu_rdg', e == 0 .and. all(pflat == pmu))
    call pressridge_mu_rdg_table_lookup(mt, 5.0e3_c_double, x, clamped)
    call check('mu_rdg table lookup clamps', x == 2.0_c_double .and. clamped)
    call pressridge_mu_rdg_table_free(mt)
    call pressridge_mu_rdg_table_new([1.0_c_double, 0.5_c_double], [2.0_c_double, 3.0_c_double], &
         mt, e)
    call check('unsorted mu_rdg table refused', e == PRESSRIDGE_ERR_BAD_VALUE)
  end block

  ! Mask: invalid columns get the fill value and are not checked.
  block
    logical :: valid(ni, nj)
    real(c_double) :: bad(ni, nj, ncat)
    valid = .true.
    valid(1:3, 2) = .false.
    bad = aicen
    bad(1:3, 2, :) = -1.0_c_double
    o = d
    o%fill = -9.0_c_double
    call pressridge_strength(bad, vicen, p, aice0=aice0, options=o, valid=valid, ierr=e)
    call read_2d(trim(dir)//'/strength_default.nc', 'strength', pref)
    call check('masked columns get the fill value', e == 0 .and. all(p(1:3, 2) == -9.0_c_double))
    call check('unmasked columns unchanged', all(p(4:, 2) == pref(4:, 2)) .and. &
         all(p(:, 3:) == pref(:, 3:)))
  end block

  ! --- ridging step against `pressridge ridge-step --dt 3600`
  block
    real(c_double) :: a(ni, nj, ncat), v(ni, nj, ncat), a0(ni, nj), ra(ni, nj, ncat), &
         rv(ni, nj, ncat), ra0(ni, nj), cl(ni, nj), rcl(ni, nj), a1(ncat), v1(ncat), a01, c1
    a = aicen
    v = vicen
    a0 = aice0
    call pressridge_ridge_step(a, v, a0, conv, shear, 3600.0_c_double, hin_max=hin_max, &
         closing=cl, ierr=e)
    call check('ridging step (block layout) succeeds', e == PRESSRIDGE_OK)
    call read_3d(trim(dir)//'/ridged.nc', 'aicen', ra)
    call read_3d(trim(dir)//'/ridged.nc', 'vicen', rv)
    call read_2d(trim(dir)//'/ridged.nc', 'aice0', ra0)
    call read_2d(trim(dir)//'/ridged.nc', 'closing', rcl)
    call check('ridged aicen = pressridge ridge-step', agree3(a, ra))
    call check('ridged vicen = pressridge ridge-step', agree3(v, rv))
    call check('ridged aice0 = pressridge ridge-step', agree(a0, ra0))
    call check('closing rate = pressridge ridge-step', agree(cl, rcl))
    call check('ice volume conserved', &
         abs(sum(v) - sum(vicen)) <= 1e-12_c_double * sum(vicen))
    ! Per cell, Icepack style.
    e = 0
    do j = 1, nj
       do i = 1, ni
          a1 = aicen(i, j, :)
          v1 = vicen(i, j, :)
          a01 = aice0(i, j)
          call pressridge_ridge_ice(3600.0_c_double, hin_max, conv(i, j), shear(i, j), a1, v1, &
               a01, closing=c1, ierr=e)
          if (e /= 0) exit
          if (any(a1 /= a(i, j, :)) .or. any(v1 /= v(i, j, :)) .or. a01 /= a0(i, j) .or. &
               c1 /= cl(i, j)) e = -1
       end do
    end do
    call check('pressridge_ridge_ice per cell = batched step', e == 0)
    ! Default bounds (no hin_max) are the sample's (CICE kcatbound = 1).
    a = aicen
    v = vicen
    a0 = aice0
    call pressridge_ridge_step(a, v, a0, conv, shear, 3600.0_c_double, ierr=e)
    call check('default bounds = the sample''s bounds', e == 0 .and. agree3(a, ra))
  end block

  ! --- errors come back as ierr, with a message
  block
    real(c_double) :: a(ncat, 3), v(ncat, 3), out(3), out2(2), a0(3), nan
    nan = ieee_value(nan, ieee_quiet_nan)
    a = 0.1_c_double
    v = 0.2_c_double
    a0 = 0.5_c_double
    call pressridge_strength(a, v, out, aice0=a0, ierr=e)
    call check('a valid call has ierr = 0 and no message', e == PRESSRIDGE_OK .and. &
         pressridge_last_error_message() == '')
    a(2, 3) = nan
    call pressridge_strength(a, v, out, aice0=a0, ierr=e)
    call check('NaN: PRESSRIDGE_ERR_NOT_FINITE', e == PRESSRIDGE_ERR_NOT_FINITE)
    call check('NaN: message names the value', index(pressridge_last_error_message(), &
         'not finite') > 0)
    call check('NaN: column 3 reported', pressridge_last_error_column() == 3)
    a(2, 3) = -0.1_c_double
    call pressridge_strength(a, v, out, aice0=a0, ierr=e)
    call check('negative area: PRESSRIDGE_ERR_BAD_VALUE', e == PRESSRIDGE_ERR_BAD_VALUE .and. &
         index(pressridge_last_error_message(), 'negative') > 0)
    a(2, 3) = 0.1_c_double
    a0(1) = 0.9_c_double
    call pressridge_strength(a, v, out, aice0=a0, ierr=e)
    call check('area sum /= 1: PRESSRIDGE_ERR_BAD_VALUE', e == PRESSRIDGE_ERR_BAD_VALUE .and. &
         pressridge_last_error_column() == 1)
    a0(1) = 0.5_c_double
    call pressridge_strength(a, v, out2, aice0=a0, ierr=e)
    call check('wrong output size: PRESSRIDGE_ERR_BAD_SIZE', e == PRESSRIDGE_ERR_BAD_SIZE .and. &
         index(pressridge_last_error_message(), 'strength') > 0)
    call pressridge_strength(a(:, 1:0), v(:, 1:0), out(1:0), ierr=e)
    call check('zero columns: PRESSRIDGE_ERR_BAD_SIZE', e == PRESSRIDGE_ERR_BAD_SIZE)
    o = d
    o%participation = 5
    call pressridge_strength(a, v, out, aice0=a0, options=o, ierr=e)
    call check('bad option: PRESSRIDGE_ERR_BAD_VALUE', e == PRESSRIDGE_ERR_BAD_VALUE .and. &
         index(pressridge_last_error_message(), 'participation') > 0)
    o = d
    o%params%rhow = 800.0_c_double
    call pressridge_strength(a, v, out, aice0=a0, options=o, ierr=e)
    call check('rhow < rhoi: PRESSRIDGE_ERR_BAD_VALUE', e == PRESSRIDGE_ERR_BAD_VALUE)
    o = d
    o%cf_source = PRESSRIDGE_CF_SOURCE_TABLE
    call pressridge_strength(a, v, out, aice0=a0, options=o, ierr=e)
    call check('C_f table missing: PRESSRIDGE_ERR_NULL_POINTER', e == PRESSRIDGE_ERR_NULL_POINTER)
    call pressridge_ice_strength(0.0_c_double, 0.0_c_double, 0.5_c_double, a(:, 1), &
         v(1:2, 1), x, ierr=e)
    call check('per cell, sizes differ: PRESSRIDGE_ERR_BAD_SIZE', e == PRESSRIDGE_ERR_BAD_SIZE)
    call pressridge_cf_table_open('no/such/file.nc', cft, e)
    call check('missing C_f table: PRESSRIDGE_ERR_IO', e == PRESSRIDGE_ERR_IO .and. &
         index(pressridge_last_error_message(), 'no/such/file.nc') > 0)
    call pressridge_cf_table_open(trim(sample), cft, e)
    call check('not a C_f table: PRESSRIDGE_ERR_IO', e == PRESSRIDGE_ERR_IO)
    call pressridge_cf_table_new([1.0_c_double, 0.5_c_double], [2.0_c_double, 3.0_c_double], &
         cft, e)
    call check('unsorted C_f nodes: PRESSRIDGE_ERR_BAD_VALUE', e == PRESSRIDGE_ERR_BAD_VALUE)
    rdg: block
      real(c_double) :: aa(ncat), vv(ncat), aa0
      aa = 0.1_c_double
      vv = 0.2_c_double
      aa0 = 0.5_c_double
      call pressridge_ridge_ice(0.0_c_double, hin_max, 1e-6_c_double, 0.0_c_double, aa, vv, &
           aa0, ierr=e)
      call check('ridging with dt = 0: PRESSRIDGE_ERR_BAD_VALUE', e == PRESSRIDGE_ERR_BAD_VALUE)
      call pressridge_ridge_ice(3600.0_c_double, hin_max(1:ncat), 1e-6_c_double, 0.0_c_double, &
           aa, vv, aa0, ierr=e)
      call check('ridging with ncat bounds: PRESSRIDGE_ERR_BAD_SIZE', e == PRESSRIDGE_ERR_BAD_SIZE)
    end block rdg
  end block

  ! --- the complete step (snow, tracers, fluxes): an optional per-category or per-column array
  ! of the wrong size is an error naming it and the size it needs, the cell is not stepped and
  ! nothing is written past the array's end (guard: the values after it stay -999)
  cstep: block
    integer, parameter :: nc = 5, nk = 3
    type(pressridge_ridger) :: rg
    integer :: nt, c, k
    real(c_double) :: hb(0:nc), an(nc, nk), vn(nc, nk), sn(nc, nk), a0(nk), ai(nk), cv(nk), &
         sh(nk), fr(nk), guard(2 * nc), a1(nc), d1, d2, d3, op, fp, fh, fs
    real(c_double), allocatable :: tr(:, :, :)
    logical :: fi(nc)
    call pressridge_ridger_init(rg, nc, 7, 1, .true., .true., .true., .true., ntrcr=nt, ierr=e)
    call check('complete step: a ridger with 23 tracers', e == PRESSRIDGE_OK .and. nt == 23)
    allocate(tr(nt, nc, nk))
    hb = [0.0_c_double, 0.6_c_double, 1.4_c_double, 2.4_c_double, 3.6_c_double, 1.0e8_c_double]
    do c = 1, nk
       do k = 1, nc
          an(k, c) = 0.19_c_double
          vn(k, c) = an(k, c) * (0.3_c_double + 0.9_c_double * (k - 1))
          sn(k, c) = 0.1_c_double * vn(k, c)
          tr(:, k, c) = [-15.0_c_double, (-3.0e8_c_double - 1.0e6_c_double * i, i = 1, 7), &
               -1.15e8_c_double, (4.0_c_double + 0.2_c_double * i, i = 1, 7), 2.0e7_c_double, &
               0.4_c_double, 0.8_c_double, 0.8_c_double, 0.2_c_double, 0.1_c_double, 0.01_c_double]
       end do
       a0(c) = 1 - sum(an(:, c))
       ai(c) = sum(an(:, c))
       cv(c) = 1.0e-6_c_double * c
       sh(c) = 1.0e-6_c_double
    end do
    op = 0
    fp = 0
    fr = 0
    fh = 0
    fs = 0
    a1 = an(:, 1)
    guard = -999
    call pressridge_step_ridge(rg, 3600.0_c_double, 1, hb, cv(1), sh(1), an(:, 1), tr(:, :, 1), &
         vn(:, 1), sn(:, 1), a0(1), d1, d2, d3, op, fp, fr(1), fh, aice=ai(1), fsalt=fs, &
         Tf=-1.8_c_double, aparticn=guard(1:nc), krdgn=guard(nc + 1:2 * nc - 1), ierr=e)
    call check('step_ridge, krdgn(ncat - 1): PRESSRIDGE_ERR_BAD_SIZE naming it, nothing written', &
         e == PRESSRIDGE_ERR_BAD_SIZE .and. &
         pressridge_last_error_message() == 'krdgn has 4 elements, expected ncat = 5' .and. &
         all(guard == -999) .and. all(an(:, 1) == a1))
    fi = .false.
    call pressridge_step_ridge(rg, 3600.0_c_double, 1, hb, cv(1), sh(1), an(:, 1), tr(:, :, 1), &
         vn(:, 1), sn(:, 1), a0(1), d1, d2, d3, op, fp, fr(1), fh, aice=ai(1), fsalt=fs, &
         Tf=-1.8_c_double, first_ice=fi(1:nc - 1), ierr=e)
    call check('step_ridge, first_ice(ncat - 1): PRESSRIDGE_ERR_BAD_SIZE naming it', &
         e == PRESSRIDGE_ERR_BAD_SIZE .and. &
         pressridge_last_error_message() == 'first_ice has 4 elements, expected ncat = 5' .and. &
         all(an(:, 1) == a1))
    call pressridge_step_ridge(rg, 3600.0_c_double, 1, hb, cv(1), sh(1), an(:, 1), tr(:, :, 1), &
         vn(:, 1), sn(:, 1), a0(1), d1, d2, d3, op, fp, fr(1), fh, aice=ai(1), fsalt=fs, &
         Tf=-1.8_c_double, aparticn=guard(1:nc), first_ice=fi, ierr=e)
    call check('step_ridge with aparticn(ncat) and first_ice(ncat) steps the cell', &
         e == PRESSRIDGE_OK .and. any(an(:, 1) /= a1) .and. all(guard(nc + 1:) == -999) .and. &
         abs(a0(1) + sum(an(:, 1)) - 1) < 1.0e-12_c_double)
    guard = -999
    a1 = an(:, 2)
    call pressridge_step_ridge_cells(rg, 3600.0_c_double, 1, hb, cv, sh, an, tr, vn, sn, a0, &
         ai, Tf=guard(1:nk - 1), ierr=e)
    call check('step_ridge_cells, Tf(ncol - 1): PRESSRIDGE_ERR_BAD_SIZE naming it', &
         e == PRESSRIDGE_ERR_BAD_SIZE .and. &
         pressridge_last_error_message() == 'Tf has 2 elements, expected ncol = 3' .and. &
         all(an(:, 2) == a1))
    call pressridge_step_ridge_cells(rg, 3600.0_c_double, 1, hb, cv, sh, an, tr, vn, sn, a0, &
         ai, fresh=guard(1:nk - 1), ierr=e)
    call check('step_ridge_cells, fresh(ncol - 1): PRESSRIDGE_ERR_BAD_SIZE, nothing written', &
         e == PRESSRIDGE_ERR_BAD_SIZE .and. &
         pressridge_last_error_message() == 'fresh has 2 elements, expected ncol = 3' .and. &
         all(guard == -999) .and. all(an(:, 2) == a1))
    call pressridge_step_ridge_cells(rg, 3600.0_c_double, 1, hb, cv, sh, an, tr, vn, sn, a0, &
         ai, closing=cv(1:nk - 1), opening=fr, ierr=e)
    call check('step_ridge_cells, closing(ncol - 1): PRESSRIDGE_ERR_BAD_SIZE naming it', &
         e == PRESSRIDGE_ERR_BAD_SIZE .and. &
         pressridge_last_error_message() == 'closing has 2 elements, expected ncol = 3')
    call pressridge_step_ridge_cells(rg, 3600.0_c_double, 1, hb, cv, sh, an, tr, vn, sn, a0, &
         ai, dvirdgdt=guard(1:nk + 1), ierr=e)
    call check('step_ridge_cells, dvirdgdt(ncol + 1): PRESSRIDGE_ERR_BAD_SIZE naming it', &
         e == PRESSRIDGE_ERR_BAD_SIZE .and. &
         pressridge_last_error_message() == 'dvirdgdt has 4 elements, expected ncol = 3')
    fr = 0
    call pressridge_step_ridge_cells(rg, 3600.0_c_double, 1, hb, cv, sh, an, tr, vn, sn, a0, &
         ai, Tf=[(-1.8_c_double, i = 1, nk)], fresh=fr, dvirdgdt=guard(1:nk), ierr=e)
    call check('step_ridge_cells with Tf, fresh and dvirdgdt of ncol values steps the cells', &
         e == PRESSRIDGE_OK .and. any(an(:, 2) /= a1) .and. all(guard(nk + 1:) == -999) .and. &
         all(abs(a0 + sum(an, 1) - 1) < 1.0e-12_c_double))
    call pressridge_ridger_free(rg)
    ! A ridger made without options= takes those of pressridge_init_parameters (here Hibler's
    ! uniform redistribution, krdg_redist = 0), as the per-cell Icepack-style calls do.
    implicit_options: block
      type(pressridge_ridger) :: rp, ro, rd
      type(pressridge_options) :: oh
      real(c_double), dimension(nc, nk) :: ap, vp, sp, ao, vo, so, ad, vd, sd
      real(c_double), dimension(nk) :: a0p, a0o, a0d, aip, aio, aid
      real(c_double), allocatable, dimension(:, :, :) :: tp, to, td
      integer :: e1, e2, e3
      call pressridge_init_parameters(krdg_redist=0)
      call pressridge_ridger_init(rp, nc, 7, 1, .true., .true., .true., .true., ierr=e1)
      call pressridge_init_parameters(options=d)
      oh = d
      oh%redistribution = 0
      call pressridge_ridger_init(ro, nc, 7, 1, .true., .true., .true., .true., options=oh, &
           ierr=e2)
      call pressridge_ridger_init(rd, nc, 7, 1, .true., .true., .true., .true., ierr=e3)
      call check('ridgers made with and without options= succeed', &
           e1 == PRESSRIDGE_OK .and. e2 == PRESSRIDGE_OK .and. e3 == PRESSRIDGE_OK)
      ap = an; vp = vn; sp = sn; a0p = a0; aip = ai; tp = tr
      ao = an; vo = vn; so = sn; a0o = a0; aio = ai; to = tr
      ad = an; vd = vn; sd = sn; a0d = a0; aid = ai; td = tr
      call pressridge_step_ridge_cells(rp, 3600.0_c_double, 1, hb, cv, sh, ap, tp, vp, sp, a0p, &
           aip, ierr=e1)
      call pressridge_step_ridge_cells(ro, 3600.0_c_double, 1, hb, cv, sh, ao, to, vo, so, a0o, &
           aio, ierr=e2)
      call pressridge_step_ridge_cells(rd, 3600.0_c_double, 1, hb, cv, sh, ad, td, vd, sd, a0d, &
           aid, ierr=e3)
      call check('ridger_init without options= takes pressridge_init_parameters'' options', &
           e1 == PRESSRIDGE_OK .and. e2 == PRESSRIDGE_OK .and. e3 == PRESSRIDGE_OK .and. &
           all(ap == ao) .and. all(vp == vo) .and. all(tp == to) .and. any(ap /= ad))
      call pressridge_ridger_free(rp)
      call pressridge_ridger_free(ro)
      call pressridge_ridger_free(rd)
    end block implicit_options
    ! The thermodynamic constants from Fortran: the type's initial values are the library's
    ! defaults, and a ridger given fsnowrdg = 1 keeps all the snow of the ridging ice.
    step_constants: block
      type(pressridge_step_params) :: sp0, sp1, spi
      type(pressridge_ridger) :: ra, rb
      real(c_double), dimension(nc, nk) :: aa, va, sa, ab, vb, sb
      real(c_double), dimension(nk) :: a0a, a0b, aia, aib
      real(c_double), allocatable, dimension(:, :, :) :: ta, tb
      integer :: e1, e2
      call pressridge_default_step_params(sp0, e1)
      call check('Fortran initial step constants equal the library''s (pressridge_step_params)', &
           e1 == PRESSRIDGE_OK .and. sp0%rhos == spi%rhos .and. sp0%lfresh == spi%lfresh .and. &
           sp0%cp_ice == spi%cp_ice .and. sp0%fsnowrdg == spi%fsnowrdg .and. &
           sp0%ice_ref_salinity == spi%ice_ref_salinity .and. &
           sp0%salt_flux_prognostic == spi%salt_flux_prognostic .and. &
           sp0%itd_area_min == spi%itd_area_min .and. sp0%itd_mass_min == spi%itd_mass_min .and. &
           sp0%hs_min == spi%hs_min .and. sp0%tmin == spi%tmin)
      sp1 = sp0
      sp1%fsnowrdg = 1.0_c_double
      call pressridge_ridger_init(ra, nc, 7, 1, .true., .true., .true., .true., ierr=e1)
      call pressridge_ridger_init(rb, nc, 7, 1, .true., .true., .true., .true., &
           step_params=sp1, ierr=e2)
      aa = an; va = vn; sa = sn; a0a = a0; aia = ai; ta = tr
      ab = an; vb = vn; sb = sn; a0b = a0; aib = ai; tb = tr
      call pressridge_step_ridge_cells(ra, 3600.0_c_double, 1, hb, cv, sh, aa, ta, va, sa, a0a, &
           aia, ierr=e1)
      call pressridge_step_ridge_cells(rb, 3600.0_c_double, 1, hb, cv, sh, ab, tb, vb, sb, a0b, &
           aib, ierr=e2)
      call check('ridger_init(step_params=): fsnowrdg = 1 keeps more snow, same ice', &
           e1 == PRESSRIDGE_OK .and. e2 == PRESSRIDGE_OK .and. sum(sb) > sum(sa) .and. &
           all(ab == aa) .and. all(vb == va))
      call pressridge_ridger_free(ra)
      call pressridge_ridger_free(rb)
    end block step_constants
    ! The tracer layout arrays: the library writes ntrcr rows of each, at the first size of
    ! those given; all must have that size, and trcr_base 3 columns, nt_strata 2.
    layout: block
      integer(c_int32_t) :: dep(64), nst(64)
      real(c_double) :: base(64, 2)
      dep = -999
      call pressridge_ridger_init(rg, nc, 7, 1, .true., .true., .true., .true., &
           trcr_depend=dep(1:10), n_trcr_strata=nst, ierr=e)
      call check('ridger_init, trcr_depend(10) with n_trcr_strata(64): PRESSRIDGE_ERR_BAD_SIZE, &
           &nothing written past it', e == PRESSRIDGE_ERR_BAD_SIZE .and. &
           pressridge_last_error_message() == 'the tracer arrays must have the same first size' &
           .and. all(dep(11:) == -999))
      call pressridge_ridger_free(rg)
      call pressridge_ridger_init(rg, nc, 7, 1, .true., .true., .true., .true., &
           trcr_base=base, ierr=e)
      call check('ridger_init, trcr_base(64, 2): PRESSRIDGE_ERR_BAD_SIZE', &
           e == PRESSRIDGE_ERR_BAD_SIZE .and. &
           pressridge_last_error_message() == 'trcr_base must have 3 columns')
      call pressridge_ridger_free(rg)
    end block layout
    ! Snow, isotope and aerosol tracers (41 with 3 isotope, 2 aerosol species): the fluxes
    ! faero_ocn, fiso_ocn of the per-cell call equal those of the batched call bit for bit,
    ! and ridged snow puts some of each into the ocean.
    species: block
      type(pressridge_ridger) :: rx
      integer :: nx
      real(c_double), allocatable :: tx(:, :, :), tc(:, :)
      real(c_double) :: ax(nc, nk), vx(nc, nk), sx(nc, nk), a0x(nk), aix(nk), fa(2, nk), &
           fi(3, nk), fa1(2), fi1(3), h1(0:nc), ac(nc), vc(nc), scn(nc), a0c, aic, op1, fp1, &
           fr1, fh1, fs1
      call pressridge_ridger_init(rx, nc, 7, 1, .true., .true., .true., .true., ntrcr=nx, &
           tr_snow=.true., n_iso=3, n_aero=2, ierr=e)
      call check('ridger_init(tr_snow, n_iso = 3, n_aero = 2): 41 tracers', &
           e == PRESSRIDGE_OK .and. nx == 41)
      allocate(tx(nx, nc, nk), tc(nx, nc))
      do c = 1, nk
         do k = 1, nc
            ax(k, c) = 0.19_c_double
            vx(k, c) = ax(k, c) * (0.3_c_double + 0.9_c_double * (k - 1))
            sx(k, c) = 0.1_c_double * vx(k, c)
            tx(1:23, k, c) = [-15.0_c_double, (-3.0e8_c_double - 1.0e6_c_double * i, i = 1, 7), &
                 -1.15e8_c_double, (4.0_c_double + 0.2_c_double * i, i = 1, 7), &
                 2.0e7_c_double, 0.4_c_double, 0.8_c_double, 0.8_c_double, 0.2_c_double, &
                 0.1_c_double, 0.01_c_double]
            tx(24:, k, c) = [(1.0e-3_c_double * (i + k), i = 24, nx)]
         end do
         a0x(c) = 1 - sum(ax(:, c))
         aix(c) = sum(ax(:, c))
      end do
      ac = ax(:, 2)
      vc = vx(:, 2)
      scn = sx(:, 2)
      tc = tx(:, :, 2)
      a0c = a0x(2)
      aic = aix(2)
      h1 = hb
      op1 = 0
      fp1 = 0
      fr1 = 0
      fh1 = 0
      fs1 = 0
      fa1 = 0
      fi1 = 0
      call pressridge_step_ridge(rx, 3600.0_c_double, 1, h1, cv(2), sh(2), ac, tc, vc, scn, &
           a0c, d1, d2, d3, op1, fp1, fr1, fh1, aice=aic, fsalt=fs1, Tf=-1.8_c_double, &
           faero_ocn=fa1, fiso_ocn=fi1, ierr=e)
      call check('step_ridge with faero_ocn(2), fiso_ocn(3) steps the cell', &
           e == PRESSRIDGE_OK .and. all(fa1 > 0) .and. all(fi1 > 0))
      fa = 0
      fi = 0
      call pressridge_step_ridge_cells(rx, 3600.0_c_double, 1, hb, cv, sh, ax, tx, vx, sx, &
           a0x, aix, faero_ocn=fa, fiso_ocn=fi, ierr=e)
      call check('step_ridge_cells faero_ocn(:, 2), fiso_ocn(:, 2) = per cell, bit for bit', &
           e == PRESSRIDGE_OK .and. all(fa(:, 2) == fa1) .and. all(fi(:, 2) == fi1) .and. &
           all(tx(:, :, 2) == tc))
      call pressridge_step_ridge_cells(rx, 3600.0_c_double, 1, hb, cv, sh, ax, tx, vx, sx, &
           a0x, aix, faero_ocn=fa(:, 1:2), ierr=e)
      call check('step_ridge_cells, faero_ocn(2, ncol - 1): PRESSRIDGE_ERR_BAD_SIZE', &
           e == PRESSRIDGE_ERR_BAD_SIZE .and. &
           pressridge_last_error_message() == 'faero_ocn must be (n_aero, ncol)')
      call pressridge_ridger_free(rx)
    end block species
  end block cstep

  ! --- ridging lookup tables
  call pressridge_ridge_table_open(trim(dir)//'/ridge_table.nc', rt, e)
  call check('ridging table opens', e == PRESSRIDGE_OK)
  call pressridge_ridge_table_dims(rt, ns, nh, nv, nf)
  call check('ridging table dims', ns == 2 .and. nh == 3 .and. nv == 2 .and. nf == 4)
  call pressridge_ridge_table_axes(rt, th, vol)
  call check('ridging table axes', all(th == [0.2_c_double, 0.3_c_double, 0.45_c_double]) .and. &
       all(vol == [0.0_c_double, 10.0_c_double]))
  call pressridge_ridge_table_set_name(rt, 2, s)
  call check('set names', s == 'contact.mu=0.5')
  call pressridge_ridge_table_variable_name(rt, 4, s)
  call check('variable names', s == 'work_mean')
  call pressridge_ridge_table_friction_set(rt, 0.5_c_double, 0.6_c_double, i)
  call check('set by friction', i == 2)
  call pressridge_ridge_table_friction_set(rt, 0.4_c_double, 0.3_c_double, i, e)
  call check('no set at that friction: PRESSRIDGE_ERR_NOT_FOUND', e == PRESSRIDGE_ERR_NOT_FOUND &
       .and. index(pressridge_last_error_message(), '(1, 0.6), (0.5, 0.6)') > 0)
  call pressridge_cf_table_open_at_friction(trim(dir)//'/ridge_table.nc', 0.5_c_double, &
       0.6_c_double, cft, e)
  call pressridge_cf_table_lookup(cft, 0.45_c_double, y)
  call pressridge_cf_table_friction(cft, x, z, known)
  call check('C_f at a friction', e == PRESSRIDGE_OK .and. y == 8.0_c_double .and. known .and. &
       x == 0.5_c_double .and. z == 0.6_c_double)
  call pressridge_cf_table_free(cft)
  call pressridge_cf_table_open_at_friction(trim(dir)//'/ridge_table.nc', 0.5_c_double, &
       -1.0_c_double, cft, e)
  call check('negative mu_w: PRESSRIDGE_ERR_BAD_VALUE', e == PRESSRIDGE_ERR_BAD_VALUE)
  call pressridge_ridge_table_value(rt, 'work_mean', 2, 0.3_c_double, 5.0_c_double, x, clamped)
  call check('table value interpolates', x == 8500.0_c_double .and. .not. clamped)
  call pressridge_ridge_table_value(rt, 'nope', 1, 0.3_c_double, 5.0_c_double, x, ierr=e)
  call check('unknown field: PRESSRIDGE_ERR_NOT_FOUND', e == PRESSRIDGE_ERR_NOT_FOUND)
  call pressridge_ridge_table_value(rt, 'work_mean', 3, 0.3_c_double, 5.0_c_double, x, ierr=e)
  call check('set out of range: PRESSRIDGE_ERR_BAD_VALUE', e == PRESSRIDGE_ERR_BAD_VALUE)
  call pressridge_ridge_table_cf(rt, 1, 1.0_c_double, x, clamped)
  call check('table C_f clamps', x == 14.0_c_double .and. clamped)
  call pressridge_ridge_table_cf_table(rt, 2, cft)
  call pressridge_ridge_table_free(rt)
  call pressridge_cf_table_lookup(cft, 0.3_c_double, y)
  call check('C_f table of a set', y == 7.0_c_double)
  call pressridge_cf_table_free(cft)
  call pressridge_ridge_table_open('missing.nc', rt, e)
  call check('missing ridging table: PRESSRIDGE_ERR_IO', e == PRESSRIDGE_ERR_IO)

  ! --- a simulator run
  block
    character(len=*), parameter :: tiny = 'name = "tiny"'//new_line('a')//'duration = 0.05' &
         //new_line('a')//'[pile]'//new_line('a')//'blocks = 4'//new_line('a')//'columns = 2'
    call pressridge_run_scene(tiny, s, e)
    call check('scene runs, summary as JSON', e == PRESSRIDGE_OK .and. &
         index(s, '"scene": "tiny"') > 0)
    call pressridge_scene_run(tiny, run, e)
    call pressridge_run_summary_value(run, 'time', x, e)
    call pressridge_run_summary_value(run, 'steps', y)
    call check('summary values', e == 0 .and. abs(x - 0.05_c_double) < 1e-3_c_double .and. &
         y > 0)
    call pressridge_run_free(run)
  end block
  call pressridge_run_scene('durration = 1', s, e)
  call check('unknown scene key: PRESSRIDGE_ERR_PARSE', e == PRESSRIDGE_ERR_PARSE .and. &
       index(pressridge_last_error_message(), 'durration') > 0)

  ! Free what the program holds, so that a leak checker (scripts/check-ub.sh asan) reports only
  ! what the library itself leaves.
  deallocate(aicen, vicen, aice0, divu, shear, conv, hin_max, p, pref, pcell, a2, v2, p1, a0_1)
  if (allocated(s)) deallocate(s)
  if (allocated(th)) deallocate(th)
  if (allocated(cf)) deallocate(cf)
  if (allocated(vol)) deallocate(vol)

  print '(i0, a, i0, a)', passed, ' passed, ', failed, ' failed'
  if (failed > 0) error stop 1

contains

  subroutine check(name, ok)
    character(len=*), intent(in) :: name
    logical, intent(in) :: ok
    if (ok) then
       passed = passed + 1
       print '(a)', 'ok     '//name
    else
       failed = failed + 1
       print '(a)', 'FAILED '//name
       print '(a)', '       last error: '//pressridge_last_error_message()
    end if
  end subroutine check

  !> Agreement to round-off: |a - b| <= tol * max|b| (default tol 1e-13).
  logical function agree(a, b, tol)
    real(c_double), intent(in) :: a(:, :), b(:, :)
    real(c_double), intent(in), optional :: tol
    real(c_double) :: t
    t = 1.0e-13_c_double
    if (present(tol)) t = tol
    agree = maxval(abs(a - b)) <= t * max(maxval(abs(b)), tiny(1.0_c_double))
    if (.not. agree) print '(a, es10.3)', '       max |difference| = ', maxval(abs(a - b))
  end function agree

  logical function agree3(a, b)
    real(c_double), intent(in) :: a(:, :, :), b(:, :, :)
    agree3 = maxval(abs(a - b)) <= 1.0e-13_c_double * maxval(abs(b))
    if (.not. agree3) print '(a, es10.3)', '       max |difference| = ', maxval(abs(a - b))
  end function agree3

  logical function same_options(a, b)
    type(pressridge_options), intent(in) :: a, b
    same_options = a%participation == b%participation .and. &
         a%redistribution == b%redistribution .and. a%strength_law == b%strength_law .and. &
         a%cf_source == b%cf_source .and. a%cf == b%cf .and. a%fill == b%fill .and. &
         a%params%rhoi == b%params%rhoi .and. a%params%rhow == b%params%rhow .and. &
         a%params%gravit == b%params%gravit .and. a%params%gstar == b%params%gstar .and. &
         a%params%astar == b%params%astar .and. a%params%hstar == b%params%hstar .and. &
         a%params%maxraft == b%params%maxraft .and. a%params%mu_rdg == b%params%mu_rdg .and. &
         a%params%cs == b%params%cs .and. a%params%pstar == b%params%pstar .and. &
         a%params%cstar == b%params%cstar .and. a%params%puny == b%params%puny .and. &
         a%params%exp_argmax == b%params%exp_argmax .and. a%params%big == b%params%big .and. &
         a%params%area_tolerance == b%params%area_tolerance .and. &
         a%params%max_area_before_ridging == b%params%max_area_before_ridging .and. &
         a%params%nitermax == b%params%nitermax
  end function same_options

end program test_pressridge
