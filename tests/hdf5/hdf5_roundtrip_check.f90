!> Runs the HDF5 results round-trip suite (tests/hdf5/hdf5_roundtrip_suite.f90). Files go to
!> $FRIX_TEST_OUTPUT_DIR (else the working directory); the three-increment file
!> hdf5_roundtrip.h5 is left there for tests/hdf5/h5py_layout_test.sh.
program hdf5_roundtrip_check
   use frix_testing, only: run_suites, new_testsuite
   use hdf5_roundtrip_suite, only: collect_hdf5_roundtrip
   implicit none
   call run_suites([new_testsuite('hdf5_roundtrip', collect_hdf5_roundtrip)])
end program hdf5_roundtrip_check
