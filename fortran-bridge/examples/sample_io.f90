!> Reading gridded thickness distributions (data/sample_itd.nc, outputs of the pressridge
!> command line) with netCDF-Fortran, for the bridge's example and tests. A NetCDF variable
!> aicen(ncat, nj, ni) reads as the Fortran array aicen(ni, nj, ncat): CICE's block layout.
module sample_io
  use, intrinsic :: iso_c_binding, only: c_double
  use netcdf
  implicit none
  private
  public :: read_grid, read_1d, read_2d, read_3d

contains

  subroutine check(status, what)
    integer, intent(in) :: status
    character(len=*), intent(in) :: what
    if (status /= nf90_noerr) then
       print '(a)', 'netCDF error: '//what//': '//trim(nf90_strerror(status))
       error stop 1
    end if
  end subroutine check

  !> Dimensions of the sample: ni, nj, ncat.
  subroutine read_grid(path, ni, nj, ncat)
    character(len=*), intent(in) :: path
    integer, intent(out) :: ni, nj, ncat
    integer :: nc, id
    call check(nf90_open(path, nf90_nowrite, nc), path)
    call check(nf90_inq_dimid(nc, 'ni', id), 'ni')
    call check(nf90_inquire_dimension(nc, id, len=ni), 'ni')
    call check(nf90_inq_dimid(nc, 'nj', id), 'nj')
    call check(nf90_inquire_dimension(nc, id, len=nj), 'nj')
    call check(nf90_inq_dimid(nc, 'ncat', id), 'ncat')
    call check(nf90_inquire_dimension(nc, id, len=ncat), 'ncat')
    call check(nf90_close(nc), path)
  end subroutine read_grid

  !> A variable on (nj, ni) as x(ni, nj).
  subroutine read_2d(path, name, x)
    character(len=*), intent(in) :: path, name
    real(c_double), intent(out) :: x(:, :)
    integer :: nc, id
    call check(nf90_open(path, nf90_nowrite, nc), path)
    call check(nf90_inq_varid(nc, name, id), path//': '//name)
    call check(nf90_get_var(nc, id, x), path//': '//name)
    call check(nf90_close(nc), path)
  end subroutine read_2d

  !> A variable on (ncat, nj, ni) as x(ni, nj, ncat).
  subroutine read_3d(path, name, x)
    character(len=*), intent(in) :: path, name
    real(c_double), intent(out) :: x(:, :, :)
    integer :: nc, id
    call check(nf90_open(path, nf90_nowrite, nc), path)
    call check(nf90_inq_varid(nc, name, id), path//': '//name)
    call check(nf90_get_var(nc, id, x), path//': '//name)
    call check(nf90_close(nc), path)
  end subroutine read_3d

  !> A 1-D variable.
  subroutine read_1d(path, name, x)
    character(len=*), intent(in) :: path, name
    real(c_double), intent(out) :: x(:)
    integer :: nc, id
    call check(nf90_open(path, nf90_nowrite, nc), path)
    call check(nf90_inq_varid(nc, name, id), path//': '//name)
    call check(nf90_get_var(nc, id, x), path//': '//name)
    call check(nf90_close(nc), path)
  end subroutine read_1d

end module sample_io
