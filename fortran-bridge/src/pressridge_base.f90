!> pressridge_base_mod: what every wrapper of the bridge shares.
!>
!> Owns the status protocol (the optional `ierr`, or a message on standard error and error
!> stop; pressridge_last_error_message and _column; errors found on the Fortran side recorded
!> as the thread's last error), strings by the C ABI's required-length protocol, the
!> versions, the options (pressridge_default_options, pressridge_options_set_cf_table) and
!> the options of the Icepack-style calls (pressridge_init_parameters, which
!> tests/params_faces.rs checks against the Rust ItdParams::FIELDS, and
!> pressridge_get_parameters), and the two column layouts of the batched calls (the C
!> grid, shape checks and C pointers for aicen(ncat, ncol) with x(ncol), and for CICE's
!> block layout aicen(nx, ny, ncat) with x(nx, ny)). Hosts `use pressridge`.
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
  public :: finish, fail, get_string, options_ptr
  public :: STRING_SET_NAME, STRING_VARIABLE_NAME, STRING_SUMMARY_JSON
  public :: columns, columns_of, fits, cptr, mask_ptr

  ! What get_string reads.
  integer, parameter :: STRING_LAST_ERROR = 0, STRING_VERSION = 1, STRING_SET_NAME = 2, &
       STRING_VARIABLE_NAME = 3, STRING_SUMMARY_JSON = 4

  !> Options used by pressridge_ice_strength and pressridge_ridge_ice (the Icepack-style
  !> calls); set with pressridge_init_parameters.
  type(pressridge_options), save, target :: icepack_options

  !> The layout of a batched call, from the rank of aicen: aicen(ncat, ncol) with per-column
  !> arrays x(ncol), or CICE's block layout aicen(nx, ny, ncat) with x(nx, ny) and
  !> ncol = nx*ny; both contiguous.
  type :: columns
     type(c_grid) :: grid   !< the layout as the C ABI takes it
     integer :: ncol = 0    !< number of columns
     integer :: rank = 1    !< rank of a per-column array: 1 (ncol) or 2 (nx, ny)
     integer :: cols(2) = 0 !< shape of a per-column array, cols(1:rank)
  end type columns

contains

  ! ------------------------------------------------------------------ errors and strings

  !> The message of the last failed pressridge call on this thread ('' after a success).
  function pressridge_last_error_message() result(msg)
    character(len=:), allocatable :: msg
    integer(c_int32_t) :: rc
    call get_string(STRING_LAST_ERROR, c_null_ptr, 0_c_int64_t, msg, rc)
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

  !> Reads a string by the required-length protocol: `what` is one of STRING_* (the last
  !> error, the version, a ridging table's set or variable name, a run's summary JSON);
  !> handle and index (from 0) say whose.
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
    case (STRING_LAST_ERROR)
       rc = c_last_error(buf, len, need)
    case (STRING_VERSION)
       rc = c_version(buf, len, need)
    case (STRING_SET_NAME)
       rc = c_ridge_table_set_name(handle, index, buf, len, need)
    case (STRING_VARIABLE_NAME)
       rc = c_ridge_table_variable_name(handle, index, buf, len, need)
    case default
       rc = c_run_summary_json(handle, buf, len, need)
    end select
  end function call_string

  !> The library version, e.g. '0.1.0'.
  function pressridge_version() result(v)
    character(len=:), allocatable :: v
    integer(c_int32_t) :: rc
    call get_string(STRING_VERSION, c_null_ptr, 0_c_int64_t, v, rc)
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

  !> The C pointer to `options`, or to the options of pressridge_init_parameters when absent.
  type(c_ptr) function options_ptr(options) result(p)
    type(pressridge_options), intent(in), optional, target :: options
    p = c_loc(icepack_options)
    if (present(options)) p = c_loc(options)
  end function options_ptr

  ! ------------------------------------------------------------------ column layouts

  !> The layout of a batched call from its aicen: rank 2 is aicen(ncat, ncol), rank 3 CICE's
  !> aicen(nx, ny, ncat). Zero sizes are passed on for the library to reject with a message.
  type(columns) function columns_of(aicen) result(c)
    real(c_double), intent(in) :: aicen(..)
    integer(c_int64_t) :: ncat, ncol
    if (rank(aicen) == 2) then
       c%rank = 1
       c%cols(1) = size(aicen, 2)
       ncat = size(aicen, 1, kind=c_int64_t)
    else
       c%rank = 2
       c%cols = [size(aicen, 1), size(aicen, 2)]
       ncat = size(aicen, 3, kind=c_int64_t)
    end if
    c%ncol = product(c%cols(1:c%rank))
    ncol = int(c%ncol, c_int64_t)
    if (c%rank == 1) then
       ! Categories contiguous within a column.
       c%grid = c_grid(ncat, ncol, 1_c_int64_t, max(ncat, 1_c_int64_t), ncat * ncol, &
            1_c_int64_t, ncol)
    else
       ! Columns contiguous within a category.
       c%grid = c_grid(ncat, ncol, max(ncol, 1_c_int64_t), 1_c_int64_t, ncat * ncol, &
            1_c_int64_t, ncol)
    end if
  end function columns_of

  !> Whether the per-column array `name` is absent or has the shape of a per-column array of
  !> layout c; if not, records PRESSRIDGE_ERR_BAD_SIZE naming it.
  logical function fits(c, x, name, where, ierr)
    type(columns), intent(in) :: c
    type(*), intent(in), optional :: x(..)
    character(len=*), intent(in) :: name, where
    integer, intent(out), optional :: ierr
    character(len=24) :: a, b
    fits = .true.
    if (.not. present(x)) return
    fits = rank(x) == c%rank
    if (fits) fits = all(shape(x) == c%cols(1:c%rank))
    if (fits) return
    if (c%rank == 1) then
       write (a, '(i0)') size(x)
       write (b, '(i0)') c%ncol
       call fail(PRESSRIDGE_ERR_BAD_SIZE, name//' has '//trim(a)// &
            ' elements, expected ncol = '//trim(b), where, ierr)
    else
       call fail(PRESSRIDGE_ERR_BAD_SIZE, name//' must have the shape (nx, ny) of aicen', &
            where, ierr)
    end if
  end function fits

  !> The C pointer to a contiguous array, or null when it is absent or empty.
  type(c_ptr) function cptr(x)
    real(c_double), intent(in), optional, contiguous, target :: x(..)
    cptr = c_null_ptr
    if (.not. present(x)) return
    if (size(x) > 0) cptr = c_loc(x)
  end function cptr

  !> The mask `valid` (of either layout) as the C ABI's flags (1 valid, 0 not) in `flags`,
  !> and the C pointer to them: null when valid is absent or empty.
  type(c_ptr) function mask_ptr(valid, flags) result(p)
    logical, intent(in), optional :: valid(..)
    integer(c_int32_t), allocatable, target, intent(out) :: flags(:)
    p = c_null_ptr
    if (.not. present(valid)) return
    allocate(flags(size(valid)))
    select rank (valid)
    rank (1)
       flags = merge(1_c_int32_t, 0_c_int32_t, valid)
    rank (2)
       flags = reshape(merge(1_c_int32_t, 0_c_int32_t, valid), [size(valid)])
    end select
    if (size(flags) > 0) p = c_loc(flags)
  end function mask_ptr

end module pressridge_base_mod
