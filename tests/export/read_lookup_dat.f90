! Reads an aerobreak lookup table (.dat, docs/EXPORT.md) the way an older Fortran system code
! would: no line is longer than 80 characters, so a CHARACTER*80 buffer holds each; the second line
! "# header_lines: H" gives the number of comment lines, "# columns: C" the column count; each index
! line "# column I NAME 'UNIT'" is read list-directed; then each row is one list-directed READ of C
! values, which continues over the row's lines. Missing values are the sentinel -1.0E+30 of
! "# missing_value:", never NaN: the tests build this reader with -ffpe-trap=invalid,zero,overflow.
! Prints "column I NAME UNIT" per index line, each value (ES25.16E3) on a line of its own, then
! "rows N", for tests/export/table_formats_test.cpp to compare with the table.
program read_lookup_dat
  implicit none
  character(len=80) :: line
  character(len=1024) :: path
  character(len=64) :: tag, name, unit_text
  integer :: unit, status, header_lines, columns, rows, i, index
  double precision, allocatable :: values(:)

  call get_command_argument(1, path)
  open(newunit=unit, file=trim(path), status='old', action='read', iostat=status)
  if (status /= 0) stop 2
  read(unit, '(A)') line
  read(unit, '(A)') line
  if (line(1:15) /= '# header_lines:') stop 3
  read(line(16:), *) header_lines
  columns = 0
  do i = 3, header_lines
    read(unit, '(A)') line
    if (line(1:10) == '# columns:') read(line(11:), *) columns
    if (line(1:9) == '# column ') then
      read(line(2:), *, iostat=status) tag, index, name, unit_text
      if (status /= 0) stop 4
      write(*, '(A,I0,A,A,A,A)') 'column ', index, ' ', trim(name), ' ', trim(unit_text)
    end if
  end do
  if (columns == 0) stop 5
  allocate(values(columns))
  rows = 0
  do
    read(unit, *, iostat=status) values
    if (status < 0) exit
    if (status > 0) stop 6
    rows = rows + 1
    do i = 1, columns
      write(*, '(ES25.16E3)') values(i)
    end do
  end do
  close(unit)
  write(*, '(A,I0)') 'rows ', rows
end program read_lookup_dat
