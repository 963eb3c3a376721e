/* Versions of the libraries frix is compiled against, for `frix --version`
 * (frix_version_info.f90.in): the version macros of SuiteSparse_config.h, cholmod.h
 * (cholmod_core.h), umfpack.h, metis.h and HDF5's H5public.h. For HDF5 the header version is
 * also the run-time one: the library's H5check aborts a program built against other headers.
 * The include directories are set for frix_core at the end of CMakeLists.txt. */
#include <stdio.h>
#include <SuiteSparse_config.h>
#include <cholmod.h>
#include <umfpack.h>
#include <metis.h>
#include <H5public.h>

/* Writes one NUL-terminated line of at most length - 1 characters into buffer. */
void frix_library_versions_c(char *buffer, int length)
{
    if (length <= 0) return;
    snprintf(buffer, (size_t)length,
             "SuiteSparse %d.%d.%d (CHOLMOD %d.%d.%d, UMFPACK %d.%d.%d), METIS %d.%d.%d, HDF5 %d.%d.%d",
             SUITESPARSE_MAIN_VERSION, SUITESPARSE_SUB_VERSION, SUITESPARSE_SUBSUB_VERSION,
             CHOLMOD_MAIN_VERSION, CHOLMOD_SUB_VERSION, CHOLMOD_SUBSUB_VERSION,
             UMFPACK_MAIN_VERSION, UMFPACK_SUB_VERSION, UMFPACK_SUBSUB_VERSION,
             METIS_VER_MAJOR, METIS_VER_MINOR, METIS_VER_SUBMINOR,
             H5_VERS_MAJOR, H5_VERS_MINOR, H5_VERS_RELEASE);
}
