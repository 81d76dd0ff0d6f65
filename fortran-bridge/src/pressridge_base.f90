!> pressridge_base_mod: what every wrapper of the bridge shares.
!>
!> Owns the status protocol (the optional `ierr`, or a message on standard error and error
!> stop; pressridge_last_error_message and _column; errors found on the Fortran side recorded
!> as the thread's last error), strings by the C ABI's required-length protocol, the
!> versions, the options (pressridge_default_options, pressridge_options_set_cf_table) and
!> the options of the Icepack-style calls (pressridge_init_parameters, which
!> tests/params_faces.rs checks against the Rust ItdParams::FIELDS, and
!> pressridge_get_parameters), and the two column layouts of the batched calls (the C grid
!> and C pointers of aicen(ncat, ncol) with x(ncol), and of CICE's block layout
!> aicen(nx, ny, ncat) with x(nx, ny)). Hosts `use pressridge`.
module pressridge_base_mod
  use, intrinsic :: iso_c_binding
  use, intrinsic :: iso_fortran_env, only: error_unit
  use pressridge_cabi_mod
  implicit none
  private

  public :: pressridge_last_error_message, pressridge_last_error_column
  public :: pressridge_version, pressridge_linked_abi_version
  public :: pressridge_default_options, pressridge_options_set_cf_table
  public :: pressridge_init_parameters, pressridge_get_parameters
  ! For the other modules of the bridge.
  public :: icepack_options, finish, fail, get_string, sized, grid_2d, grid_3d, ptr1, ptr2, ptr3

  !> Options used by pressridge_ice_strength and pressridge_ridge_ice (the Icepack-style
  !> calls); set with pressridge_init_parameters.
  type(pressridge_options), save, target :: icepack_options

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

end module pressridge_base_mod
