/* SPDX-License-Identifier: MIT */
/*
 * Atomic file replacement: write a temporary file beside the target, make it
 * durable, rename it over the target.  rename() within one directory is
 * atomic, so readers see either the old file or the complete new one, and a
 * failure at any step leaves the old file as it was.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "posix_internal.h"

/* errno after a failed step; 0 would print "Success", which misleads. */
static int saved_errno(void)
{
    return errno != 0 ? errno : EIO;
}

static int write_stdout(stp_posix_emit_fn emit, void *ctx, char *err, size_t errlen)
{
    int e;

    errno = 0;
    if (emit(stdout, ctx) != 0) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "stdout: write failed: %s", strerror(e));
        return -1;
    }
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "stdout: write failed: %s", strerror(e));
        return -1;
    }
    return 0;
}

/* The permission bits the finished file should have: those of the file it
 * replaces, else what open(..., 0666) would give.  mkstemp makes 0600, which
 * would silently hide a picture from other users. */
static mode_t target_mode(const char *path)
{
    struct stat st;
    mode_t mask;

    if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
        return st.st_mode & 07777;
    mask = umask(0);
    umask(mask);
    return (mode_t)(0666 & ~mask);
}

/* Makes the rename itself durable.  Best effort: some file systems reject
 * fsync on a directory, and the file's data is already safe. */
static void sync_directory(const char *path, size_t dirlen)
{
    char *dir;
    int fd;

    if (dirlen == 0) {
        dir = NULL;
    } else {
        dir = (char *)malloc(dirlen + 1);
        if (dir == NULL)
            return;
        memcpy(dir, path, dirlen);
        dir[dirlen] = '\0';
    }
    fd = open(dir != NULL ? dir : ".", O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        (void)fsync(fd);
        (void)close(fd);
    }
    free(dir);
}

int stp_posix_write_file(const char *path, stp_posix_emit_fn emit, void *ctx,
                         char *err, size_t errlen)
{
    const char *slash;
    const char *base;
    size_t dirlen;
    char *tmp;
    mode_t mode;
    FILE *fp;
    int fd;
    int e;

    if (path == NULL || *path == '\0' || emit == NULL) {
        stp_posix_priv_error(err, errlen, "%s: invalid arguments to the file writer",
                             path != NULL && *path != '\0' ? path : "(no path)");
        return -1;
    }
    if (strcmp(path, "-") == 0)
        return write_stdout(emit, ctx, err, errlen);

    slash = strrchr(path, '/');
    dirlen = slash != NULL ? (size_t)(slash - path) + 1u : 0u; /* keeps the '/' */
    base = path + dirlen;
    if (*base == '\0') {
        stp_posix_priv_error(err, errlen, "%s: names a directory, not a file", path);
        return -1;
    }
    /* "<dir>/.<name>.XXXXXX": same directory (so rename is atomic), hidden,
     * and recognisably the target's if a crash leaves it behind. */
    tmp = (char *)malloc(dirlen + 1u + strlen(base) + 8u);
    if (tmp == NULL) {
        stp_posix_priv_error(err, errlen, "%s: %s", path, strerror(ENOMEM));
        return -1;
    }
    memcpy(tmp, path, dirlen);
    tmp[dirlen] = '\0';
    strcat(tmp, ".");
    strcat(tmp, base);
    strcat(tmp, ".XXXXXX");

    mode = target_mode(path);
    fd = mkstemp(tmp);
    if (fd < 0) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot create temporary file %s: %s",
                             path, tmp, strerror(e));
        free(tmp);
        return -1;
    }
    if (fchmod(fd, mode) != 0) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot set permissions of %s: %s",
                             path, tmp, strerror(e));
        (void)close(fd);
        goto fail;
    }
    fp = fdopen(fd, "wb");
    if (fp == NULL) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot open stream on %s: %s",
                             path, tmp, strerror(e));
        (void)close(fd);
        goto fail;
    }
    errno = 0;
    if (emit(fp, ctx) != 0 || fflush(fp) != 0 || ferror(fp)) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot write %s: %s", path, tmp, strerror(e));
        (void)fclose(fp);
        goto fail;
    }
    if (fsync(fileno(fp)) != 0) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot sync %s: %s", path, tmp, strerror(e));
        (void)fclose(fp);
        goto fail;
    }
    if (fclose(fp) != 0) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot close %s: %s", path, tmp, strerror(e));
        goto fail;
    }
    if (rename(tmp, path) != 0) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot rename %s over it: %s",
                             path, tmp, strerror(e));
        goto fail;
    }
    sync_directory(path, dirlen);
    free(tmp);
    return 0;

fail:
    (void)unlink(tmp);
    free(tmp);
    return -1;
}
