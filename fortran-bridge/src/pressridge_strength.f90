!> pressridge_strength_mod: ice strength P (N/m), Rothrock (1975) or Hibler (1979), as
!> CICE/Icepack's icepack_ice_strength.
!>
!> Owns pressridge_ice_strength (one cell, Icepack's argument list, the options of
!> pressridge_init_parameters) and the batched generic pressridge_strength: two thin
!> rank-specific entry points, strength_2d (aicen(ncat, ncol), x(ncol)) and strength_3d
!> (CICE's block layout aicen(nx, ny, ncat), x(nx, ny)), over one implementation,
!> strength_columns, which takes the caller's arrays as array_arg describes them (shape and
!> address; no copies) and reads the layout from the rank of aicen. Hosts `use pressridge`.
module pressridge_strength_mod
  use, intrinsic :: iso_c_binding
  use pressridge_cabi_mod
  use pressridge_base_mod
  implicit none
  private

  public :: pressridge_strength, pressridge_ice_strength

  !> Ice strength P (N/m) of many columns in one call: aicen(ncat, ncol) with x(ncol), or
  !> CICE's block layout aicen(nx, ny, ncat) with x(nx, ny).
  interface pressridge_strength
     module procedure strength_2d, strength_3d
  end interface pressridge_strength

contains

  !> Icepack-compatible: the same arguments as icepack_ice_strength (aice, vice, aice0, aicen,
  !> vicen, strength), so a host swaps one call. Options: `options`, else those of
  !> pressridge_init_parameters (CICE's defaults otherwise). strength (N/m) is overwritten, not accumulated (CICE sets it
  !> to 0 before its call). aice and vice are accepted for compatibility; the library uses
  !> sum(aicen) and sum(vicen). Errors (NaN, negative, |aice0 + sum(aicen) - 1| > 1e-6) come
  !> back in ierr, or stop the program when ierr is absent.
  subroutine pressridge_ice_strength(aice, vice, aice0, aicen, vicen, strength, ierr, options)
    real(c_double), intent(in) :: aice, vice
    real(c_double), intent(in), target :: aice0
    real(c_double), intent(in), contiguous, target :: aicen(:), vicen(:)
    real(c_double), intent(inout), target :: strength
    integer, intent(out), optional :: ierr
    type(pressridge_options), intent(in), optional, target :: options
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
         options_ptr(options), c_loc(strength))
    call finish(rc, 'pressridge_ice_strength', ierr)
  end subroutine pressridge_ice_strength

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
    call strength_columns(arg_real2(aicen), arg_real2(vicen), arg_real1(strength), &
         opt_real1(aice0), options, opt_mask1(valid), valid, cf_clamped_columns, ierr)
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
    call strength_columns(arg_real3(aicen), arg_real3(vicen), arg_real2(strength), &
         opt_real2(aice0), options, opt_mask2(valid), valid, cf_clamped_columns, ierr)
  end subroutine strength_3d

  !> The batched strength in either layout (columns_of), on the arrays of strength_2d or
  !> strength_3d as array_arg describes them: shapes checked, then one call of the C ABI on
  !> the caller's memory.
  subroutine strength_columns(aicen, vicen, strength, aice0, options, valid, mask, &
       cf_clamped_columns, ierr)
    type(array_arg), intent(in) :: aicen, vicen, strength, aice0
    type(pressridge_options), intent(in), optional, target :: options
    type(array_arg), intent(in) :: valid
    logical, intent(in), optional :: mask(*)  !< valid's values
    integer, intent(out), optional :: cf_clamped_columns
    integer, intent(out), optional :: ierr
    character(len=*), parameter :: where = 'pressridge_strength'
    type(columns) :: c
    integer(c_int32_t), allocatable, target :: flags(:)
    integer(c_int64_t), target :: nclamped
    integer(c_int32_t) :: rc
    if (.not. columns_of(aicen, vicen, c, where, ierr)) return
    if (.not. fits(c, [strength, aice0, valid], [character(len=8) :: 'strength', 'aice0', &
         'valid'], where, ierr)) return
    rc = c_strength(c%grid, aicen%ptr, vicen%ptr, aice0%ptr, mask_ptr(valid, mask, flags), &
         options_ptr(options), strength%ptr, c_loc(nclamped))
    if (rc == PRESSRIDGE_OK .and. present(cf_clamped_columns)) cf_clamped_columns = int(nclamped)
    call finish(rc, where, ierr)
  end subroutine strength_columns

end module pressridge_strength_mod
