/* Checked, buffered text output behind frix_text_output. libgfortran 12 reports no error
 * when a formatted unit's data cannot be written (ENOSPC on a full disk: WRITE, FLUSH and
 * CLOSE all return iostat 0), hence these few POSIX calls. Each function returns 0 or the
 * errno of the failure. A failed write cuts the file back to its length at the last
 * successful flush (at open for a file never flushed), so that it ends with whole lines of
 * whole increments. A file opened as a replacement is written to `<path>.tmp`, renamed to
 * `<path>` by a successful close and removed otherwise: `<path>` is always a complete
 * version. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { capacity = 1 << 16 };   /* bytes buffered before they are written */

enum { replace_mode = 0, append_mode = 1, replacement_mode = 2 };

typedef struct {
  int fd;
  char *path;        /* the file's name, NULL unless opened as a replacement */
  char *temporary;   /* <path>.tmp, the name it is written under until the close */
  off_t committed;   /* length of the file after the last successful flush */
  int failed;        /* a write has failed: a replacement is not renamed */
  size_t used;
  char data[capacity];
} text_file;

static int failure(void) { return errno != 0 ? errno : EIO; }

/* Write the buffered bytes (all of them, or the error after cutting the file back to its
 * committed length: cutting needs no space, also on a full disk). */
static int drain(text_file *file) {
  size_t done = 0;
  int status, cut;
  while (done < file->used) {
    ssize_t n = write(file->fd, file->data + done, file->used - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      status = failure();
      file->used = 0;
      file->failed = 1;
      cut = ftruncate(file->fd, file->committed);
      (void)cut;   /* the write's error is the one reported */
      return status;
    }
    done += (size_t)n;
  }
  file->used = 0;
  return 0;
}

/* Open path for writing, mode 0: replaced, 1: appended to, 2: replaced on a successful
 * close (written to <path>.tmp until then). */
text_file *frix_text_open(const char *path, int mode, int *status) {
  text_file *file = malloc(sizeof *file);
  const char *name = path;
  if (file == NULL) {
    *status = ENOMEM;
    return NULL;
  }
  file->path = NULL;
  file->temporary = NULL;
  if (mode == replacement_mode) {
    file->path = strdup(path);
    file->temporary = malloc(strlen(path) + 5);
    if (file->path == NULL || file->temporary == NULL) {
      free(file->path);
      free(file->temporary);
      free(file);
      *status = ENOMEM;
      return NULL;
    }
    strcat(strcpy(file->temporary, path), ".tmp");
    name = file->temporary;
  }
  errno = 0;
  file->fd = open(name, O_WRONLY | O_CREAT | O_CLOEXEC | (mode == append_mode ? O_APPEND : O_TRUNC), 0666);
  file->used = 0;
  file->failed = 0;
  if (file->fd < 0) {
    *status = failure();
    free(file->path);
    free(file->temporary);
    free(file);
    return NULL;
  }
  file->committed = lseek(file->fd, 0, SEEK_END);
  *status = 0;
  return file;
}

/* Append `length` characters and a line feed. */
int frix_text_put(text_file *file, const char *text, size_t length) {
  while (length + 1 > capacity - file->used) {
    size_t part = capacity - file->used;
    if (part > length) part = length;
    memcpy(file->data + file->used, text, part);
    file->used += part;
    text += part;
    length -= part;
    if (file->used == capacity && drain(file) != 0) return failure();
  }
  memcpy(file->data + file->used, text, length);
  file->used += length;
  file->data[file->used++] = '\n';
  return 0;
}

/* Hand the buffered lines to the system. */
int frix_text_flush(text_file *file) {
  int status;
  errno = 0;
  status = drain(file);
  if (status == 0) file->committed = lseek(file->fd, 0, SEEK_END);
  return status;
}

/* Write what is buffered and close; the file is released in every case. Returns 0, the
 * errno of a failed write (positive) or minus the errno of a failed close or rename. With
 * `discard` non-zero a replacement is removed instead of renamed. */
int frix_text_close(text_file *file, int discard) {
  int status;
  errno = 0;
  status = drain(file);
  errno = 0;
  if (close(file->fd) != 0 && status == 0) status = -failure();
  if (file->temporary != NULL) {
    errno = 0;
    if (file->failed) discard = 1;
    if (status == 0 && !discard && rename(file->temporary, file->path) != 0) status = -failure();
    if (status != 0 || discard) unlink(file->temporary);
  }
  free(file->path);
  free(file->temporary);
  free(file);
  return status;
}

/* The message of errno value `code`, cut to `length` characters and blank-padded. */
void frix_text_reason(int code, char *text, size_t length) {
  const char *reason = strerror(code);
  size_t n = strlen(reason);
  if (n > length) n = length;
  memcpy(text, reason, n);
  memset(text + n, ' ', length - n);
}
