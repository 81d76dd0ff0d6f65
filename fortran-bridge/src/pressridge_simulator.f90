!> pressridge_simulator_mod: what the ridge simulator gives a host.
!>
!> Owns the C_f tables (pressridge_cf_table_*: open a NetCDF table or one of a ridging table
!> at a friction pair, build one from nodes, look C_f up; the strength options use them),
!> the ridging lookup tables of `pressridge tabulate` (pressridge_ridge_table_*: axes, sets,
!> fields, interpolated values, C_f) and runs of the simulator on a TOML scene
!> (pressridge_scene_run, pressridge_run_summary_*, pressridge_run_free,
!> pressridge_run_scene). Sets and fields count from 1. Hosts `use pressridge`.
module pressridge_simulator_mod
  use, intrinsic :: iso_c_binding
  use pressridge_cabi_mod
  use pressridge_base_mod
  implicit none
  private

  public :: pressridge_cf_table_open, pressridge_cf_table_new, pressridge_cf_table_lookup
  public :: pressridge_cf_table_nodes, pressridge_cf_table_free
  public :: pressridge_cf_table_open_at_friction, pressridge_cf_table_friction
  public :: pressridge_mu_rdg_table_open, pressridge_mu_rdg_table_new
  public :: pressridge_mu_rdg_table_lookup, pressridge_mu_rdg_table_free
  public :: pressridge_ridge_table_open, pressridge_ridge_table_dims
  public :: pressridge_ridge_table_axes, pressridge_ridge_table_set_name
  public :: pressridge_ridge_table_variable_name, pressridge_ridge_table_value
  public :: pressridge_ridge_table_cf, pressridge_ridge_table_cf_table
  public :: pressridge_ridge_table_friction_set
  public :: pressridge_ridge_table_free
  public :: pressridge_scene_run, pressridge_run_summary_json, pressridge_run_summary_value
  public :: pressridge_run_free, pressridge_run_scene

contains

  ! ------------------------------------------------------------------ C_f tables

  !> Opens a C_f table (NetCDF with 1-D `thickness` (m) and `cf` (1)).
  subroutine pressridge_cf_table_open(path, table, ierr)
    character(len=*), intent(in) :: path
    type(pressridge_cf_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    call finish(c_cf_table_open(path, len(path, kind=c_int64_t), table%ptr), &
         'pressridge_cf_table_open('//path//')', ierr)
  end subroutine pressridge_cf_table_open

  !> The C_f at friction mu (between blocks above the water line) and mu_w (below it; both
  !> dimensionless) of a ridging table of `pressridge tabulate`; PRESSRIDGE_ERR_NOT_FOUND,
  !> with the pairs the table has in the message, when it has no set at that friction.
  subroutine pressridge_cf_table_open_at_friction(path, mu, mu_w, table, ierr)
    character(len=*), intent(in) :: path
    real(c_double), intent(in) :: mu, mu_w
    type(pressridge_cf_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    call finish(c_cf_table_open_at_friction(path, len(path, kind=c_int64_t), mu, mu_w, &
         table%ptr), 'pressridge_cf_table_open_at_friction('//path//')', ierr)
  end subroutine pressridge_cf_table_open_at_friction

  !> The friction pair (mu, mu_w; dimensionless) a C_f table is for; known is .false. (and
  !> mu, mu_w NaN) when the table does not say.
  subroutine pressridge_cf_table_friction(table, mu, mu_w, known, ierr)
    type(pressridge_cf_table), intent(in) :: table
    real(c_double), intent(out) :: mu, mu_w
    logical, intent(out) :: known
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: k
    k = 0
    call finish(c_cf_table_friction(table%ptr, mu, mu_w, k), 'pressridge_cf_table_friction', &
         ierr)
    known = k /= 0
  end subroutine pressridge_cf_table_friction

  !> A C_f table from nodes: thickness (m, strictly increasing) and cf (1, > 0).
  subroutine pressridge_cf_table_new(thickness, cf, table, ierr)
    real(c_double), intent(in) :: thickness(:), cf(:)
    type(pressridge_cf_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    real(c_double) :: t1(max(size(thickness), 1)), c1(max(size(thickness), 1))
    if (size(cf) /= size(thickness)) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'cf and thickness differ in size', &
            'pressridge_cf_table_new', ierr)
       return
    end if
    t1(1:size(thickness)) = thickness
    c1(1:size(cf)) = cf
    call finish(c_cf_table_new(t1, c1, size(thickness, kind=c_int64_t), table%ptr), &
         'pressridge_cf_table_new', ierr)
  end subroutine pressridge_cf_table_new

  !> C_f (1) at ridging-ice thickness h (m); clamped is .true. outside the table's range.
  subroutine pressridge_cf_table_lookup(table, h, cf, clamped, ierr)
    type(pressridge_cf_table), intent(in) :: table
    real(c_double), intent(in) :: h
    real(c_double), intent(out) :: cf
    logical, intent(out), optional :: clamped
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: c, rc
    rc = c_cf_table_lookup(table%ptr, h, cf, c)
    if (present(clamped)) clamped = c /= 0
    call finish(rc, 'pressridge_cf_table_lookup', ierr)
  end subroutine pressridge_cf_table_lookup

  !> The nodes of a C_f table: thickness (m) and cf (1).
  subroutine pressridge_cf_table_nodes(table, thickness, cf, ierr)
    type(pressridge_cf_table), intent(in) :: table
    real(c_double), allocatable, intent(out) :: thickness(:), cf(:)
    integer, intent(out), optional :: ierr
    integer(c_int64_t) :: n
    integer(c_int32_t) :: rc
    rc = c_cf_table_len(table%ptr, n)
    if (rc /= PRESSRIDGE_OK) then
       call finish(rc, 'pressridge_cf_table_nodes', ierr)
       return
    end if
    allocate(thickness(n), cf(n))
    call finish(c_cf_table_nodes(table%ptr, thickness, cf, n), 'pressridge_cf_table_nodes', ierr)
  end subroutine pressridge_cf_table_nodes

  !> Releases a C_f table (no options may use it afterwards).
  subroutine pressridge_cf_table_free(table)
    type(pressridge_cf_table), intent(inout) :: table
    integer(c_int32_t) :: rc
    rc = c_cf_table_free(table%ptr)
    table%ptr = c_null_ptr
  end subroutine pressridge_cf_table_free

  ! ------------------------------------------------------------------ mu_rdg tables

  !> Opens the mu_rdg (m^0.5) against thickness of a ridging table of `pressridge tabulate`
  !> at friction mu, mu_w (dimensionless), for PRESSRIDGE_REDISTRIBUTION_TABLE.
  subroutine pressridge_mu_rdg_table_open(path, mu, mu_w, table, ierr)
    character(len=*), intent(in) :: path
    real(c_double), intent(in) :: mu, mu_w
    type(pressridge_mu_rdg_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    call finish(c_mu_rdg_table_open(path, len(path, kind=c_int64_t), mu, mu_w, table%ptr), &
         'pressridge_mu_rdg_table_open('//path//')', ierr)
  end subroutine pressridge_mu_rdg_table_open

  !> A mu_rdg table from nodes: thickness (m, strictly increasing) and mu_rdg (m^0.5).
  subroutine pressridge_mu_rdg_table_new(thickness, mu_rdg, table, ierr)
    real(c_double), intent(in) :: thickness(:), mu_rdg(:)
    type(pressridge_mu_rdg_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    real(c_double) :: t1(max(size(thickness), 1)), m1(max(size(thickness), 1))
    if (size(mu_rdg) /= size(thickness)) then
       call fail(PRESSRIDGE_ERR_BAD_SIZE, 'mu_rdg and thickness differ in size', &
            'pressridge_mu_rdg_table_new', ierr)
       return
    end if
    t1(1:size(thickness)) = thickness
    m1(1:size(mu_rdg)) = mu_rdg
    call finish(c_mu_rdg_table_new(t1, m1, size(thickness, kind=c_int64_t), table%ptr), &
         'pressridge_mu_rdg_table_new', ierr)
  end subroutine pressridge_mu_rdg_table_new

  !> mu_rdg (m^0.5) at thickness h (m); clamped is .true. outside the table's nodes.
  subroutine pressridge_mu_rdg_table_lookup(table, h, mu_rdg, clamped, ierr)
    type(pressridge_mu_rdg_table), intent(in) :: table
    real(c_double), intent(in) :: h
    real(c_double), intent(out) :: mu_rdg
    logical, intent(out), optional :: clamped
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: c, rc
    rc = c_mu_rdg_table_lookup(table%ptr, h, mu_rdg, c)
    if (present(clamped)) clamped = c /= 0
    call finish(rc, 'pressridge_mu_rdg_table_lookup', ierr)
  end subroutine pressridge_mu_rdg_table_lookup

  !> Releases a mu_rdg table (options using it must not be used afterwards).
  subroutine pressridge_mu_rdg_table_free(table)
    type(pressridge_mu_rdg_table), intent(inout) :: table
    integer(c_int32_t) :: rc
    rc = c_mu_rdg_table_free(table%ptr)
    table%ptr = c_null_ptr
  end subroutine pressridge_mu_rdg_table_free

  ! ------------------------------------------------------------------ ridging tables

  !> Opens a ridging lookup table written by `pressridge tabulate`.
  subroutine pressridge_ridge_table_open(path, table, ierr)
    character(len=*), intent(in) :: path
    type(pressridge_ridge_table), intent(out) :: table
    integer, intent(out), optional :: ierr
    call finish(c_ridge_table_open(path, len(path, kind=c_int64_t), table%ptr), &
         'pressridge_ridge_table_open('//path//')', ierr)
  end subroutine pressridge_ridge_table_open

  !> Numbers of sets, thickness nodes, volume nodes and fields.
  subroutine pressridge_ridge_table_dims(table, nsets, nthickness, nvolume, nvariables, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(out) :: nsets, nthickness, nvolume, nvariables
    integer, intent(out), optional :: ierr
    integer(c_int64_t) :: a, b, c, d
    integer(c_int32_t) :: rc
    a = 0; b = 0; c = 0; d = 0
    rc = c_ridge_table_dims(table%ptr, a, b, c, d)
    nsets = int(a); nthickness = int(b); nvolume = int(c); nvariables = int(d)
    call finish(rc, 'pressridge_ridge_table_dims', ierr)
  end subroutine pressridge_ridge_table_dims

  !> The thickness (m) and volume (m3/m) axes.
  subroutine pressridge_ridge_table_axes(table, thickness, volume, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    real(c_double), allocatable, intent(out) :: thickness(:), volume(:)
    integer, intent(out), optional :: ierr
    integer :: ns, nh, nv, nf, e
    call pressridge_ridge_table_dims(table, ns, nh, nv, nf, e)
    if (e /= PRESSRIDGE_OK) then
       call finish(int(e, c_int32_t), 'pressridge_ridge_table_axes', ierr)
       return
    end if
    allocate(thickness(nh), volume(nv))
    e = c_ridge_table_thickness(table%ptr, thickness, int(nh, c_int64_t))
    if (e == PRESSRIDGE_OK) e = c_ridge_table_volume(table%ptr, volume, int(nv, c_int64_t))
    call finish(int(e, c_int32_t), 'pressridge_ridge_table_axes', ierr)
  end subroutine pressridge_ridge_table_axes

  !> The label of set `set` (from 1).
  subroutine pressridge_ridge_table_set_name(table, set, name, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(in) :: set
    character(len=:), allocatable, intent(out) :: name
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: rc
    call get_string(STRING_SET_NAME, table%ptr, int(set - 1, c_int64_t), name, rc)
    call finish(rc, 'pressridge_ridge_table_set_name', ierr)
  end subroutine pressridge_ridge_table_set_name

  !> The name of field `index` (from 1, sorted by name).
  subroutine pressridge_ridge_table_variable_name(table, index, name, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(in) :: index
    character(len=:), allocatable, intent(out) :: name
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: rc
    call get_string(STRING_VARIABLE_NAME, table%ptr, int(index - 1, c_int64_t), name, rc)
    call finish(rc, 'pressridge_ridge_table_variable_name', ierr)
  end subroutine pressridge_ridge_table_variable_name

  !> Field `name` of set `set` (from 1) at thickness (m) and volume (m3/m), interpolated
  !> (the field's units; NaN where the table has no data); clamped outside the table.
  subroutine pressridge_ridge_table_value(table, name, set, thickness, volume, value, clamped, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    character(len=*), intent(in) :: name
    integer, intent(in) :: set
    real(c_double), intent(in) :: thickness, volume
    real(c_double), intent(out) :: value
    logical, intent(out), optional :: clamped
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: c, rc
    c = 0
    rc = c_ridge_table_value(table%ptr, name, len(name, kind=c_int64_t), &
         int(set - 1, c_int64_t), thickness, volume, value, c)
    if (present(clamped)) clamped = c /= 0
    call finish(rc, 'pressridge_ridge_table_value('//name//')', ierr)
  end subroutine pressridge_ridge_table_value

  !> C_f (1) of set `set` (from 1) at ridging-ice thickness (m).
  subroutine pressridge_ridge_table_cf(table, set, thickness, cf, clamped, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(in) :: set
    real(c_double), intent(in) :: thickness
    real(c_double), intent(out) :: cf
    logical, intent(out), optional :: clamped
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: c, rc
    c = 0
    rc = c_ridge_table_cf(table%ptr, int(set - 1, c_int64_t), thickness, cf, c)
    if (present(clamped)) clamped = c /= 0
    call finish(rc, 'pressridge_ridge_table_cf', ierr)
  end subroutine pressridge_ridge_table_cf

  !> The C_f of set `set` (from 1) as a new C_f table for the strength options.
  subroutine pressridge_ridge_table_cf_table(table, set, cf_table, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    integer, intent(in) :: set
    type(pressridge_cf_table), intent(out) :: cf_table
    integer, intent(out), optional :: ierr
    call finish(c_ridge_table_cf_table(table%ptr, int(set - 1, c_int64_t), cf_table%ptr), &
         'pressridge_ridge_table_cf_table', ierr)
  end subroutine pressridge_ridge_table_cf_table

  !> The set (1-based) of a ridging table at friction mu, mu_w (dimensionless);
  !> PRESSRIDGE_ERR_NOT_FOUND when the table has no such set or no friction coordinates.
  subroutine pressridge_ridge_table_friction_set(table, mu, mu_w, set, ierr)
    type(pressridge_ridge_table), intent(in) :: table
    real(c_double), intent(in) :: mu, mu_w
    integer, intent(out) :: set
    integer, intent(out), optional :: ierr
    integer(c_int64_t) :: s0
    s0 = -1
    call finish(c_ridge_table_friction_set(table%ptr, mu, mu_w, s0), &
         'pressridge_ridge_table_friction_set', ierr)
    set = int(s0) + 1
  end subroutine pressridge_ridge_table_friction_set

  !> Releases a ridging lookup table.
  subroutine pressridge_ridge_table_free(table)
    type(pressridge_ridge_table), intent(inout) :: table
    integer(c_int32_t) :: rc
    rc = c_ridge_table_free(table%ptr)
    table%ptr = c_null_ptr
  end subroutine pressridge_ridge_table_free

  ! ------------------------------------------------------------------ simulator

  !> Runs the scene given as TOML text (the format of the scene files in data/scenes) on this thread.
  subroutine pressridge_scene_run(toml, run, ierr)
    character(len=*), intent(in) :: toml
    type(pressridge_run), intent(out) :: run
    integer, intent(out), optional :: ierr
    call finish(c_scene_run(toml, len(toml, kind=c_int64_t), run%ptr), 'pressridge_scene_run', &
         ierr)
  end subroutine pressridge_scene_run

  !> The run's summary as JSON (summary.json of `pressridge simulate`).
  subroutine pressridge_run_summary_json(run, json, ierr)
    type(pressridge_run), intent(in) :: run
    character(len=:), allocatable, intent(out) :: json
    integer, intent(out), optional :: ierr
    integer(c_int32_t) :: rc
    call get_string(STRING_SUMMARY_JSON, run%ptr, 0_c_int64_t, json, rc)
    call finish(rc, 'pressridge_run_summary_json', ierr)
  end subroutine pressridge_run_summary_json

  !> One number of the run's summary by key (e.g. 'work' in J/m, 'steps').
  subroutine pressridge_run_summary_value(run, key, value, ierr)
    type(pressridge_run), intent(in) :: run
    character(len=*), intent(in) :: key
    real(c_double), intent(out) :: value
    integer, intent(out), optional :: ierr
    call finish(c_run_summary_value(run%ptr, key, len(key, kind=c_int64_t), value), &
         'pressridge_run_summary_value('//key//')', ierr)
  end subroutine pressridge_run_summary_value

  !> Releases a run.
  subroutine pressridge_run_free(run)
    type(pressridge_run), intent(inout) :: run
    integer(c_int32_t) :: rc
    rc = c_run_free(run%ptr)
    run%ptr = c_null_ptr
  end subroutine pressridge_run_free

  !> Runs a scene (TOML text) and returns its summary as JSON in one call.
  subroutine pressridge_run_scene(toml, json, ierr)
    character(len=*), intent(in) :: toml
    character(len=:), allocatable, intent(out) :: json
    integer, intent(out), optional :: ierr
    type(pressridge_run) :: run
    integer :: e
    json = ''
    call pressridge_scene_run(toml, run, e)
    if (e == PRESSRIDGE_OK) then
       call pressridge_run_summary_json(run, json, e)
       call pressridge_run_free(run)
    end if
    call finish(int(e, c_int32_t), 'pressridge_run_scene', ierr)
  end subroutine pressridge_run_scene

end module pressridge_simulator_mod
