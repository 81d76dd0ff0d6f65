!> A stand-in for the part of Icepack's interface the drop-in (icepack/pressridge_icepack.F90)
!> uses, so that the test command builds and runs it without Icepack: the tracer-flag, size
!> and parameter queries read the public values below (set by the test), and the warnings
!> are collected. Argument names as Icepack 1.5's; only those the drop-in passes.
module icepack_warnings
  implicit none
  private
  public :: icepack_warnings_add, icepack_warnings_setabort
  logical, public, save :: stub_aborted = .false.
  character(len=400), public, save :: stub_message = ''
contains
  subroutine icepack_warnings_add(msg)
    character(len=*), intent(in) :: msg
    stub_message = msg
  end subroutine icepack_warnings_add
  subroutine icepack_warnings_setabort(abortflag, file, line)
    logical, intent(in) :: abortflag
    character(len=*), intent(in), optional :: file
    integer, intent(in), optional :: line
    stub_aborted = abortflag
    if (.false. .and. present(file) .and. present(line)) stub_aborted = .true.
  end subroutine icepack_warnings_setabort
end module icepack_warnings

module icepack_intfc
  implicit none
  private
  public :: icepack_query_tracer_flags, icepack_query_tracer_sizes, icepack_query_parameters, &
       icepack_query_tracer_indices
  integer, parameter, public :: icepack_max_nbtrcr = 29
  integer, parameter :: dp = kind(1.0d0)
  !> Tracer flags: iage, FY, lvl, pond_lvl, pond_topo, pond_sealvl, snow, brine, fsd, iso, aero.
  logical, public, save :: stub_flags(11) = .false.
  !> nilyr, nslyr, nblyr, n_aero, n_iso, nbtrcr, nfsd.
  integer, public, save :: stub_sizes(7) = [7, 1, 1, 0, 0, 0, 1]
  integer, public, save :: stub_kstrength = 1, stub_krdg_partic = 1, stub_krdg_redist = 1
  real(dp), public, save :: stub_mu_rdg = 3.0_dp
  ! Biogeochemistry: ntrcr_o (0: none set), skl_bgc, z_tracers, sk_l (m), bio_index.
  integer, public, save :: stub_ntrcr_o = 0
  !> The brine fraction's tracer (0: none), as Icepack's nt_fbri.
  integer, public, save :: stub_nt_fbri = 0
  logical, public, save :: stub_skl_bgc = .false., stub_z_tracers = .false.
  real(dp), public, save :: stub_sk_l = 0.03_dp
  integer, public, save :: stub_bio_index(icepack_max_nbtrcr) = 0
contains
  subroutine icepack_query_tracer_flags(tr_iage_out, tr_FY_out, tr_lvl_out, tr_pond_lvl_out, &
       tr_pond_topo_out, tr_pond_sealvl_out, tr_snow_out, tr_brine_out, tr_fsd_out, &
       tr_iso_out, tr_aero_out)
    logical, intent(out), optional :: tr_iage_out, tr_FY_out, tr_lvl_out, tr_pond_lvl_out, &
         tr_pond_topo_out, tr_pond_sealvl_out, tr_snow_out, tr_brine_out, tr_fsd_out, &
         tr_iso_out, tr_aero_out
    if (present(tr_iage_out)) tr_iage_out = stub_flags(1)
    if (present(tr_FY_out)) tr_FY_out = stub_flags(2)
    if (present(tr_lvl_out)) tr_lvl_out = stub_flags(3)
    if (present(tr_pond_lvl_out)) tr_pond_lvl_out = stub_flags(4)
    if (present(tr_pond_topo_out)) tr_pond_topo_out = stub_flags(5)
    if (present(tr_pond_sealvl_out)) tr_pond_sealvl_out = stub_flags(6)
    if (present(tr_snow_out)) tr_snow_out = stub_flags(7)
    if (present(tr_brine_out)) tr_brine_out = stub_flags(8)
    if (present(tr_fsd_out)) tr_fsd_out = stub_flags(9)
    if (present(tr_iso_out)) tr_iso_out = stub_flags(10)
    if (present(tr_aero_out)) tr_aero_out = stub_flags(11)
  end subroutine icepack_query_tracer_flags

  subroutine icepack_query_tracer_sizes(nilyr_out, nslyr_out, nblyr_out, n_aero_out, &
       n_iso_out, nbtrcr_out, nfsd_out, ntrcr_o_out)
    integer, intent(out), optional :: nilyr_out, nslyr_out, nblyr_out, n_aero_out, &
         n_iso_out, nbtrcr_out, nfsd_out, ntrcr_o_out
    if (present(ntrcr_o_out)) ntrcr_o_out = stub_ntrcr_o
    if (present(nilyr_out)) nilyr_out = stub_sizes(1)
    if (present(nslyr_out)) nslyr_out = stub_sizes(2)
    if (present(nblyr_out)) nblyr_out = stub_sizes(3)
    if (present(n_aero_out)) n_aero_out = stub_sizes(4)
    if (present(n_iso_out)) n_iso_out = stub_sizes(5)
    if (present(nbtrcr_out)) nbtrcr_out = stub_sizes(6)
    if (present(nfsd_out)) nfsd_out = stub_sizes(7)
  end subroutine icepack_query_tracer_sizes

  subroutine icepack_query_tracer_indices(bio_index_out, nt_fbri_out)
    integer, intent(out), optional :: bio_index_out(:), nt_fbri_out
    if (present(bio_index_out)) bio_index_out = stub_bio_index
    if (present(nt_fbri_out)) nt_fbri_out = stub_nt_fbri
  end subroutine icepack_query_tracer_indices

  !> Icepack's defaults for every value the drop-in reads.
  subroutine icepack_query_parameters(kstrength_out, krdg_partic_out, krdg_redist_out, &
       mu_rdg_out, Cf_out, Pstar_out, Cstar_out, rhoi_out, rhow_out, rhos_out, gravit_out, &
       Lfresh_out, cp_ice_out, ice_ref_salinity_out, itd_area_min_out, itd_mass_min_out, &
       hs_min_out, saltflux_option_out, snwredist_out, snwgrain_out, rhosnew_out, &
       rsnw_fall_out, skl_bgc_out, z_tracers_out, sk_l_out)
    integer, intent(out), optional :: kstrength_out, krdg_partic_out, krdg_redist_out
    real(dp), intent(out), optional :: mu_rdg_out, Cf_out, Pstar_out, Cstar_out, rhoi_out, &
         rhow_out, rhos_out, gravit_out, Lfresh_out, cp_ice_out, ice_ref_salinity_out, &
         itd_area_min_out, itd_mass_min_out, hs_min_out, rhosnew_out, rsnw_fall_out, sk_l_out
    character(len=*), intent(out), optional :: saltflux_option_out, snwredist_out
    logical, intent(out), optional :: snwgrain_out, skl_bgc_out, z_tracers_out
    if (present(skl_bgc_out)) skl_bgc_out = stub_skl_bgc
    if (present(z_tracers_out)) z_tracers_out = stub_z_tracers
    if (present(sk_l_out)) sk_l_out = stub_sk_l
    if (present(kstrength_out)) kstrength_out = stub_kstrength
    if (present(krdg_partic_out)) krdg_partic_out = stub_krdg_partic
    if (present(krdg_redist_out)) krdg_redist_out = stub_krdg_redist
    if (present(mu_rdg_out)) mu_rdg_out = stub_mu_rdg
    if (present(Cf_out)) Cf_out = 17.0_dp
    if (present(Pstar_out)) Pstar_out = 2.75e4_dp
    if (present(Cstar_out)) Cstar_out = 20.0_dp
    if (present(rhoi_out)) rhoi_out = 917.0_dp
    if (present(rhow_out)) rhow_out = 1026.0_dp
    if (present(rhos_out)) rhos_out = 330.0_dp
    if (present(gravit_out)) gravit_out = 9.80616_dp
    if (present(Lfresh_out)) Lfresh_out = 2.835e6_dp - 2.501e6_dp
    if (present(cp_ice_out)) cp_ice_out = 2106.0_dp
    if (present(ice_ref_salinity_out)) ice_ref_salinity_out = 4.0_dp
    if (present(itd_area_min_out)) itd_area_min_out = 1.0e-11_dp
    if (present(itd_mass_min_out)) itd_mass_min_out = 1.0e-10_dp
    if (present(hs_min_out)) hs_min_out = 1.0e-4_dp
    if (present(saltflux_option_out)) saltflux_option_out = 'constant'
    if (present(snwredist_out)) snwredist_out = 'none'
    if (present(snwgrain_out)) snwgrain_out = .false.
    if (present(rhosnew_out)) rhosnew_out = 100.0_dp
    if (present(rsnw_fall_out)) rsnw_fall_out = 54.526_dp
  end subroutine icepack_query_parameters
end module icepack_intfc
