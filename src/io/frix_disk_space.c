/* Whether a file can grow by a number of bytes: the file is extended by them (fallocate(2))
 * and cut back to its length at once. frix_hdf5_file asks before it writes an increment
 * into the HDF5 results: an HDF5 file whose writes fail half-way cannot be closed cleanly
 * (HDF5 1.10 flushes the increment's metadata in part), one that is left alone stays as its
 * last flush made it. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

/* 0 when `bytes` more fit (or the file system cannot tell: no fallocate), else the errno
 * (ENOSPC on a full disk). */
int frix_room_to_grow(const char *path, long long bytes) {
  struct stat info;
  int fd, status = 0;
  if (bytes <= 0) return 0;
  fd = open(path, O_WRONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  if (fstat(fd, &info) != 0) {
    status = errno;
  } else if (fallocate(fd, 0, info.st_size, (off_t)bytes) != 0) {
    if (errno != EOPNOTSUPP && errno != ENOSYS) status = errno;
  } else if (ftruncate(fd, info.st_size) != 0) {
    status = errno;
  }
  close(fd);
  return status;
}
