! Reads an aerobreak lookup table (.dat, docs/EXPORT.md) the way a Fortran system code would: lines
! starting with '#' are comments, the "# columns:" line gives the column count, every other line is
! one row read with list-directed input. Prints each value (ES25.16E3) on a line of its own, then
! "rows N", for tests/export/table_formats_test.cpp to compare with the table.
program read_lookup_dat
  implicit none
  character(len=16384) :: line
  character(len=1024) :: path
  integer :: unit, status, columns, rows, i
  double precision, allocatable :: values(:)

  call get_command_argument(1, path)
  open(newunit=unit, file=trim(path), status='old', action='read', iostat=status)
  if (status /= 0) stop 2
  columns = 0
  rows = 0
  do
    read(unit, '(A)', iostat=status) line
    if (status /= 0) exit
    if (line(1:1) == '#') then
      if (line(1:10) == '# columns:') read(line(11:), *) columns
      cycle
    end if
    if (columns == 0) stop 3
    if (.not. allocated(values)) allocate(values(columns))
    read(line, *, iostat=status) values
    if (status /= 0) stop 4
    rows = rows + 1
    do i = 1, columns
      write(*, '(ES25.16E3)') values(i)
    end do
  end do
  close(unit)
  write(*, '(A,I0)') 'rows ', rows
end program read_lookup_dat
