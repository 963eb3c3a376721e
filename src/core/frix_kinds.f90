!> The one kinds module of frix: every real is `real(dp)`, every large count `integer(i8)`.
module frix_kinds
   use, intrinsic :: iso_fortran_env, only: real64, int64, int32
   implicit none
   private

   public :: dp, i8, i4

   integer, parameter :: dp = real64  !! double precision for all floating point work
   integer, parameter :: i8 = int64   !! 64-bit integers (byte counts, nonzero counts of large matrices)
   integer, parameter :: i4 = int32   !! 32-bit integers (indices handed to SuiteSparse `_di_` and METIS)
end module frix_kinds
