/* Write-failure injection for the tests (docs/testing.md, "Write failures"): loaded with
 * LD_PRELOAD, it makes the writes into chosen files fail as on a full disk (ENOSPC) once a
 * number of bytes has gone into them, whatever layer writes them (write(2), pwrite(2),
 * writev(2): frix's text files, HDF5's sec2 driver, libgfortran's units; fallocate(2) too).
 *   FRIX_FAIL_WRITE_AFTER  bytes the files concerned may grow by in total; a write beyond
 *                          fails with ENOSPC (one crossing the limit is cut short at it),
 *                          rewriting bytes inside a file works; unset or empty: nothing fails
 *   FRIX_FAIL_WRITE_PATH   substring of the paths of the files concerned (e.g. ".h5",
 *                          "_listing.txt"); unset or empty: every regular file
 *   FRIX_FAIL_WRITE_STRICT set (non-empty): every byte counts, rewrites inside a file fail
 *                          too, and fallocate(2) is never refused: writes that fail where
 *                          the space seemed to be there (a failing device)
 *   FRIX_FAIL_WRITE_REPORT a file created (empty) when the first write is refused, so that a
 *                          test knows whether the run met a failure
 *   FRIX_KILL_AT_WRITE     with FRIX_FAIL_WRITE_PATH: the process kills itself (SIGKILL) at
 *                          its N-th write into the files concerned, before that write; for
 *                          files a run killed at any point must leave readable
 * Only regular files are concerned, never pipes or the standard streams (even redirected to
 * a file). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

static long long accepted = 0;   /* bytes the files concerned have grown by so far */
static long long writes = 0;     /* writes into the files concerned so far */

/* Whether writes into fd are subject to the limit. */
static int concerned(int fd) {
  const char *after = getenv("FRIX_FAIL_WRITE_AFTER");
  const char *kill_at = getenv("FRIX_KILL_AT_WRITE");
  const char *pattern = getenv("FRIX_FAIL_WRITE_PATH");
  char link[64], path[PATH_MAX];
  struct stat info;
  ssize_t n;
  if (fd <= 2) return 0;
  if ((after == NULL || *after == '\0') && (kill_at == NULL || *kill_at == '\0')) return 0;
  if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) return 0;
  if (pattern == NULL || *pattern == '\0') return 1;
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  n = readlink(link, path, sizeof path - 1);
  if (n < 0) return 0;
  path[n] = '\0';
  return strstr(path, pattern) != NULL;
}

/* A write is refused: ENOSPC, and the report file if one is asked for. */
static ssize_t refuse(void) {
  const char *report = getenv("FRIX_FAIL_WRITE_REPORT");
  int fd;
  if (report != NULL && *report != '\0') {
    fd = open(report, O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd >= 0) close(fd);
  }
  errno = ENOSPC;
  return -1;
}

/* Bytes of a write of count bytes at offset into fd that may go through; -1 (errno ENOSPC)
 * if none. As on a full disk, rewriting bytes inside the file always works: only the bytes
 * that extend it count. */
static ssize_t allowed(int fd, size_t count, off_t offset) {
  struct stat info;
  const char *after = getenv("FRIX_FAIL_WRITE_AFTER"), *kill_at = getenv("FRIX_KILL_AT_WRITE");
  long long left, beyond;
  if (count == 0 || !concerned(fd) || fstat(fd, &info) != 0) return (ssize_t)count;
  ++writes;
  if (kill_at != NULL && *kill_at != '\0' && writes >= atoll(kill_at)) raise(SIGKILL);
  if (after == NULL || *after == '\0') return (ssize_t)count;
  beyond = (long long)offset + (long long)count - (long long)info.st_size;
  if (getenv("FRIX_FAIL_WRITE_STRICT") != NULL && *getenv("FRIX_FAIL_WRITE_STRICT") != '\0') beyond = (long long)count;
  if (beyond <= 0) return (ssize_t)count;
  left = atoll(after) - accepted;
  if (beyond <= left) {
    accepted += beyond;
    return (ssize_t)count;
  }
  if (left <= 0 || (long long)count - beyond + left <= 0) {
    accepted += left > 0 ? left : 0;
    return refuse();
  }
  accepted += left;
  return (ssize_t)((long long)count - beyond + left);
}

/* Where a write(2) into fd lands: the end of the file in append mode, else the position. */
static off_t write_offset(int fd) {
  struct stat info;
  int flags = fcntl(fd, F_GETFL);
  if (flags != -1 && (flags & O_APPEND) && fstat(fd, &info) == 0) return info.st_size;
  return lseek(fd, 0, SEEK_CUR);
}

ssize_t write(int fd, const void *buffer, size_t count) {
  static ssize_t (*real)(int, const void *, size_t) = NULL;
  ssize_t ok = allowed(fd, count, write_offset(fd));
  if (real == NULL) real = (ssize_t (*)(int, const void *, size_t))dlsym(RTLD_NEXT, "write");
  return ok < 0 ? -1 : real(fd, buffer, (size_t)ok);
}

ssize_t pwrite(int fd, const void *buffer, size_t count, off_t offset) {
  static ssize_t (*real)(int, const void *, size_t, off_t) = NULL;
  ssize_t ok = allowed(fd, count, offset);
  if (real == NULL) real = (ssize_t (*)(int, const void *, size_t, off_t))dlsym(RTLD_NEXT, "pwrite");
  return ok < 0 ? -1 : real(fd, buffer, (size_t)ok, offset);
}

ssize_t pwrite64(int fd, const void *buffer, size_t count, off_t offset) {
  return pwrite(fd, buffer, count, offset);
}

ssize_t writev(int fd, const struct iovec *vector, int n) {
  static ssize_t (*real)(int, const struct iovec *, int) = NULL;
  size_t count = 0;
  int i;
  if (real == NULL) real = (ssize_t (*)(int, const struct iovec *, int))dlsym(RTLD_NEXT, "writev");
  for (i = 0; i < n; ++i) count += vector[i].iov_len;
  if (allowed(fd, count, write_offset(fd)) != (ssize_t)count) return refuse();   /* whole only */
  return real(fd, vector, n);
}

/* Space asked for ahead (frix_disk_space.c): refused as a write of the same bytes would be,
 * without counting them (the file is cut back at once). */
int fallocate(int fd, int mode, off_t offset, off_t length) {
  static int (*real)(int, int, off_t, off_t) = NULL;
  long long saved = accepted, saved_writes = writes;
  ssize_t ok;
  if (real == NULL) real = (int (*)(int, int, off_t, off_t))dlsym(RTLD_NEXT, "fallocate");
  ok = allowed(fd, (size_t)length, offset);
  accepted = saved;
  writes = saved_writes;
  if (ok != (ssize_t)length && getenv("FRIX_FAIL_WRITE_STRICT") == NULL) return (int)refuse();
  return real(fd, mode, offset, length);
}

int fallocate64(int fd, int mode, off_t offset, off_t length) {
  return fallocate(fd, mode, offset, length);
}
