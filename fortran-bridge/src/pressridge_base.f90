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
!> block layout aicen(nx, ny, ncat) with x(nx, ny); array_arg describes an array of either
!> rank, without copying it, to a routine that serves both layouts). Hosts `use pressridge`.
module pressridge_base_mod
  use, intrinsic :: iso_c_binding
  use, intrinsic :: iso_fortran_env, only: error_unit
  use pressridge_cabi_mod
  implicit none
  private

  public :: pressridge_last_error_message, pressridge_last_error_column
  public :: pressridge_version, pressridge_linked_abi_version
  public :: pressridge_default_options, pressridge_options_set_cf_table
  public :: pressridge_options_set_mu_rdg_table
  public :: pressridge_default_step_params
  public :: pressridge_init_parameters, pressridge_get_parameters
  ! For the other modules of the bridge.
  public :: finish, fail, get_string, options_ptr
  public :: STRING_SET_NAME, STRING_VARIABLE_NAME, STRING_SUMMARY_JSON
  public :: array_arg, arg_real1, arg_real2, arg_real3, opt_real1, opt_real2, opt_int1, opt_int2
  public :: opt_mask1, opt_mask2
  public :: mask_ptr, columns, columns_of, fits, sized

  ! What get_string reads.
  integer, parameter :: STRING_LAST_ERROR = 0, STRING_VERSION = 1, STRING_SET_NAME = 2, &
       STRING_VARIABLE_NAME = 3, STRING_SUMMARY_JSON = 4

  !> Options used by pressridge_ice_strength and pressridge_ridge_ice (the Icepack-style
  !> calls); set with pressridge_init_parameters.
  type(pressridge_options), save, target :: icepack_options

  !> An array argument as a routine shared by both layouts sees it: the rank-specific entry
  !> points describe each of their arrays (arg_real1 ... arg_real3 for required ones,
  !> opt_real1, opt_mask1 and the like for optional ones) and pass the descriptions on, so that
  !> one routine serves every rank in Fortran 2008 (no assumed rank) without copying the
  !> arrays. Holds whether the array is present, its shape and the C pointer to its first
  !> element (null when absent or empty, and for a logical mask, whose values the shared
  !> routine takes beside it as an assumed-size array). The pointer is valid while the entry
  !> point runs: its dummy arguments are contiguous and have the TARGET attribute.
  type :: array_arg
     logical :: present = .false.    !< whether the optional argument is present
     integer :: rank = 0             !< its rank
     integer :: shape(3) = 0         !< its shape, shape(1:rank)
     integer :: n = 0                !< its number of elements
     type(c_ptr) :: ptr = c_null_ptr !< its first element (null: absent, empty, a mask)
  end type array_arg

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

  !> The library's thermodynamic constants of the ridging step (Icepack's; the initial values
  !> of type pressridge_step_params equal them, tested).
  subroutine pressridge_default_step_params(params, ierr)
    type(pressridge_step_params), intent(out) :: params
    integer, intent(out), optional :: ierr
    call finish(c_step_params_default(params), 'pressridge_default_step_params', ierr)
  end subroutine pressridge_default_step_params

  !> Makes `options` look C_f up in `table` (borrowed: keep it alive while in use).
  subroutine pressridge_options_set_cf_table(options, table)
    type(pressridge_options), intent(inout) :: options
    type(pressridge_cf_table), intent(in) :: table
    options%cf_source = PRESSRIDGE_CF_SOURCE_TABLE
    options%cf_table = table%ptr
  end subroutine pressridge_options_set_cf_table

  !> Makes `options` spread ridged ice exponentially with mu_rdg per category thickness from
  !> `table` (redistribution = PRESSRIDGE_REDISTRIBUTION_TABLE; borrowed: keep it alive while
  !> the options are in use; pressridge_ridger_init copies it).
  subroutine pressridge_options_set_mu_rdg_table(options, table)
    type(pressridge_options), intent(inout) :: options
    type(pressridge_mu_rdg_table), intent(in) :: table
    options%redistribution = PRESSRIDGE_REDISTRIBUTION_TABLE
    options%mu_rdg_table = table%ptr
  end subroutine pressridge_options_set_mu_rdg_table

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

  !> The description (array_arg) of a required contiguous real(c_double) array of rank 1 to 3
  !> of a wrapper.
  type(array_arg) function arg_real1(x) result(a)
    real(c_double), intent(in), contiguous, target :: x(:)
    a = described(shape(x), real_address(size(x), x))
  end function arg_real1

  type(array_arg) function arg_real2(x) result(a)
    real(c_double), intent(in), contiguous, target :: x(:, :)
    a = described(shape(x), real_address(size(x), x))
  end function arg_real2

  type(array_arg) function arg_real3(x) result(a)
    real(c_double), intent(in), contiguous, target :: x(:, :, :)
    a = described(shape(x), real_address(size(x), x))
  end function arg_real3

  !> The description of an optional contiguous array of a wrapper: opt_real1 and opt_real2 of
  !> real(c_double) arrays of rank 1 and 2, opt_int1 and opt_int2 of integer(c_int32_t) ones,
  !> opt_mask1 and opt_mask2 of logical masks. (One name a type and rank, not a generic: a
  !> generic cannot tell absent arguments of different ranks apart. Required arrays go to
  !> arg_real1 and the like: gfortran takes a zero-size array without storage, as a packed
  !> empty section may be, for an absent one.)
  type(array_arg) function opt_real1(x) result(a)
    real(c_double), intent(in), optional, contiguous, target :: x(:)
    if (present(x)) a = arg_real1(x)
  end function opt_real1

  type(array_arg) function opt_real2(x) result(a)
    real(c_double), intent(in), optional, contiguous, target :: x(:, :)
    if (present(x)) a = arg_real2(x)
  end function opt_real2

  type(array_arg) function opt_int1(x) result(a)
    integer(c_int32_t), intent(in), optional, contiguous, target :: x(:)
    if (present(x)) a = described(shape(x), int_address(size(x), x))
  end function opt_int1

  type(array_arg) function opt_int2(x) result(a)
    integer(c_int32_t), intent(in), optional, contiguous, target :: x(:, :)
    if (present(x)) a = described(shape(x), int_address(size(x), x))
  end function opt_int2

  type(array_arg) function opt_mask1(x) result(a)
    logical, intent(in), optional :: x(:)
    if (present(x)) a = described(shape(x), c_null_ptr)
  end function opt_mask1

  type(array_arg) function opt_mask2(x) result(a)
    logical, intent(in), optional :: x(:, :)
    if (present(x)) a = described(shape(x), c_null_ptr)
  end function opt_mask2

  !> A present array of shape `shape` whose first element is at `ptr`.
  type(array_arg) function described(shape, ptr) result(a)
    integer, intent(in) :: shape(:)
    type(c_ptr), intent(in) :: ptr
    a%present = .true.
    a%rank = size(shape)
    a%shape(1:a%rank) = shape
    a%n = product(shape)
    a%ptr = ptr
  end function described

  !> The C pointer to the first of the n values of x (a contiguous array of any rank, by
  !> sequence association), or null when n = 0.
  type(c_ptr) function real_address(n, x) result(p)
    integer, intent(in) :: n
    real(c_double), intent(in), target :: x(*)
    p = c_null_ptr
    if (n > 0) p = c_loc(x(1))
  end function real_address

  type(c_ptr) function int_address(n, x) result(p)
    integer, intent(in) :: n
    integer(c_int32_t), intent(in), target :: x(*)
    p = c_null_ptr
    if (n > 0) p = c_loc(x(1))
  end function int_address

  !> The mask `valid` (described by opt_mask1 or opt_mask2, its values in `mask`, of either
  !> rank, by sequence association) as the C ABI's flags (1 valid, 0 not) in `flags`, and the
  !> C pointer to them: null when valid is absent or empty.
  type(c_ptr) function mask_ptr(valid, mask, flags) result(p)
    type(array_arg), intent(in) :: valid
    logical, intent(in), optional :: mask(*)
    integer(c_int32_t), allocatable, target, intent(out) :: flags(:)
    p = c_null_ptr
    if (valid%n == 0) return
    allocate(flags(valid%n))
    flags = merge(1_c_int32_t, 0_c_int32_t, mask(1:valid%n))
    p = c_loc(flags(1))
  end function mask_ptr

  !> The layout c of a batched call from its aicen: rank 2 is aicen(ncat, ncol), rank 3 CICE's
  !> aicen(nx, ny, ncat). Zero sizes are passed on for the library to reject with a message.
  !> Whether vicen has the shape of aicen; if not, records PRESSRIDGE_ERR_BAD_SIZE.
  logical function columns_of(aicen, vicen, c, where, ierr)
    type(array_arg), intent(in) :: aicen, vicen
    type(columns), intent(out) :: c
    character(len=*), intent(in) :: where
    integer, intent(out), optional :: ierr
    integer(c_int64_t) :: ncat, ncol
    if (aicen%rank == 2) then
       c%rank = 1
       c%cols(1) = aicen%shape(2)
       ncat = aicen%shape(1)
    else
       c%rank = 2
       c%cols = aicen%shape(1:2)
       ncat = aicen%shape(3)
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
    columns_of = all(vicen%shape == aicen%shape)
    if (.not. columns_of) call fail(PRESSRIDGE_ERR_BAD_SIZE, 'vicen and aicen differ in shape', &
         where, ierr)
  end function columns_of

  !> Whether each array of `xs` (named `names`) is absent or has the shape of a per-column
  !> array of layout c; if not, records PRESSRIDGE_ERR_BAD_SIZE naming the first that has not.
  logical function fits(c, xs, names, where, ierr)
    type(columns), intent(in) :: c
    type(array_arg), intent(in) :: xs(:)
    character(len=*), intent(in) :: names(:), where
    integer, intent(out), optional :: ierr
    integer :: i
    if (c%rank == 1) then
       fits = sized(xs, names, c%ncol, 'ncol', where, ierr)
       return
    end if
    fits = .true.
    do i = 1, size(xs)
       if (.not. xs(i)%present) cycle
       if (all(xs(i)%shape(1:2) == c%cols)) cycle
       call fail(PRESSRIDGE_ERR_BAD_SIZE, trim(names(i))// &
            ' must have the shape (nx, ny) of aicen', where, ierr)
       fits = .false.
       return
    end do
  end function fits

  !> Whether each array of `xs` (named `names`) is absent or has n elements; if not, records
  !> PRESSRIDGE_ERR_BAD_SIZE naming the first that has not: "aice0 has 3 elements, expected
  !> ncol = 4", with `count` the name of n.
  logical function sized(xs, names, n, count, where, ierr)
    type(array_arg), intent(in) :: xs(:)
    character(len=*), intent(in) :: names(:), count, where
    integer, intent(in) :: n
    integer, intent(out), optional :: ierr
    character(len=24) :: a, b
    integer :: i
    sized = .true.
    do i = 1, size(xs)
       if (.not. xs(i)%present .or. xs(i)%n == n) cycle
       write (a, '(i0)') xs(i)%n
       write (b, '(i0)') n
       call fail(PRESSRIDGE_ERR_BAD_SIZE, trim(names(i))//' has '//trim(a)// &
            ' elements, expected '//count//' = '//trim(b), where, ierr)
       sized = .false.
       return
    end do
  end function sized

end module pressridge_base_mod
