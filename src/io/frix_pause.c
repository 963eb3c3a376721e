/* A pause of the calling thread (nanosleep(2)), for the HDF5 writer's retries while a
 * reader holds the results file open (frix_hdf5_file). */
#include <errno.h>
#include <time.h>

void frix_pause_c(double seconds) {
  struct timespec request, remaining;
  if (!(seconds > 0.0)) return;
  request.tv_sec = (time_t)seconds;
  request.tv_nsec = (long)((seconds - (double)request.tv_sec) * 1e9);
  while (nanosleep(&request, &remaining) != 0 && errno == EINTR) request = remaining;
}
