/* SPDX-License-Identifier: MIT */
/*
 * Atomic file replacement: write a temporary file beside the target, make it
 * durable, rename it over the target.  rename() within one directory is
 * atomic, so readers see either the old file or the complete new one, and a
 * failure at any step leaves the old file as it was.  A symbolic link is
 * followed (its target is replaced, the link stays); a character device or
 * FIFO is written in place (renaming over /dev/stdout would replace the
 * device node); SIGINT, SIGTERM and SIGHUP remove the temporary file.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
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

/* ---- the temporary file and the signals that must not strand it ---- */

/* What a signal handler may touch: the temporary file's name (written only
 * while the signals are blocked) and whether one exists.  One write at a
 * time per process, which the stipple command is. */
static char pending_tmp[PATH_MAX + 16];
static volatile sig_atomic_t pending_armed;
static const int cleanup_signals[] = {SIGINT, SIGTERM, SIGHUP};
#define CLEANUP_SIGNALS ((int)(sizeof cleanup_signals / sizeof cleanup_signals[0]))
static struct sigaction saved_actions[CLEANUP_SIGNALS];
static int saved_installed[CLEANUP_SIGNALS];

/* Async-signal-safe: unlink, sigaction and raise only. */
static void remove_tmp_and_reraise(int sig)
{
    struct sigaction dfl;
    if (pending_armed)
        (void)unlink(pending_tmp);
    pending_armed = 0;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    (void)sigaction(sig, &dfl, NULL);
    (void)raise(sig); /* delivered when the handler returns: the default
                         action, so the exit status says which signal */
}

static void block_cleanup_signals(sigset_t *old)
{
    sigset_t set;
    int i;
    sigemptyset(&set);
    for (i = 0; i < CLEANUP_SIGNALS; i++)
        sigaddset(&set, cleanup_signals[i]);
    (void)sigprocmask(SIG_BLOCK, &set, old);
}

/* Handlers for the signals the process does not ignore (nohup's SIGHUP
 * stays ignored). */
static void install_cleanup(void)
{
    int i;
    for (i = 0; i < CLEANUP_SIGNALS; i++) {
        struct sigaction act;
        saved_installed[i] = 0;
        if (sigaction(cleanup_signals[i], NULL, &saved_actions[i]) != 0 ||
            saved_actions[i].sa_handler == SIG_IGN)
            continue;
        memset(&act, 0, sizeof act);
        act.sa_handler = remove_tmp_and_reraise;
        sigemptyset(&act.sa_mask);
        if (sigaction(cleanup_signals[i], &act, NULL) == 0)
            saved_installed[i] = 1;
    }
}

static void uninstall_cleanup(void)
{
    int i;
    for (i = 0; i < CLEANUP_SIGNALS; i++)
        if (saved_installed[i])
            (void)sigaction(cleanup_signals[i], &saved_actions[i], NULL);
}

/* ---- where the bytes go ---------------------------------------------- */

/* A file opened in place (device, FIFO, or append: a file the shell
 * redirected stdout to, which '>' left empty and '>>' wants appended to):
 * bytes written, no rename. */
static int write_in_place(const char *path, stp_posix_emit_fn emit, void *ctx, int append,
                          char *err, size_t errlen)
{
    FILE *fp;
    int fd, e;
    fd = open(path, O_WRONLY | O_NOCTTY | (append ? O_APPEND : 0));
    if (fd < 0) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot open: %s", path, strerror(e));
        return -1;
    }
    fp = fdopen(fd, "wb");
    if (fp == NULL) {
        e = saved_errno();
        (void)close(fd);
        stp_posix_priv_error(err, errlen, "%s: cannot open stream: %s", path, strerror(e));
        return -1;
    }
    errno = 0;
    if (emit(fp, ctx) != 0 || fflush(fp) != 0 || ferror(fp)) {
        e = saved_errno();
        (void)fclose(fp);
        stp_posix_priv_error(err, errlen, "%s: write failed: %s", path, strerror(e));
        return -1;
    }
    if (fclose(fp) != 0) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot close: %s", path, strerror(e));
        return -1;
    }
    return 0;
}

/* The file a chain of symbolic links ends at (malloc'ed; the path itself
 * when it is no link), and whether the chain went through /proc (a magic
 * link to an open descriptor, such as /dev/stdout: its target must be
 * written in place, not replaced).  NULL with errno on failure (ELOOP
 * after 40 links). */
static char *follow_links(const char *path, int *via_proc)
{
    char *cur = strdup(path);
    int hops;
    *via_proc = 0;
    if (cur == NULL)
        return NULL;
    for (hops = 0; hops < 40; hops++) {
        struct stat st;
        char target[PATH_MAX];
        ssize_t n;
        char *next;
        if (strncmp(cur, "/proc/", 6) == 0)
            *via_proc = 1;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
            return cur; /* missing (a new file) or the end of the chain */
        n = readlink(cur, target, sizeof target - 1);
        if (n < 0) {
            free(cur);
            return NULL;
        }
        target[n] = '\0';
        if (target[0] == '/') {
            next = strdup(target);
        } else {
            /* relative to the link's directory */
            const char *slash = strrchr(cur, '/');
            size_t dl = slash != NULL ? (size_t)(slash - cur) + 1u : 0u;
            next = (char *)malloc(dl + (size_t)n + 1u);
            if (next != NULL) {
                memcpy(next, cur, dl);
                memcpy(next + dl, target, (size_t)n + 1u);
            }
        }
        free(cur);
        if (next == NULL)
            return NULL;
        cur = next;
    }
    free(cur);
    errno = ELOOP;
    return NULL;
}

static int replace_atomically(const char *path, stp_posix_emit_fn emit, void *ctx,
                              char *err, size_t errlen)
{
    const char *slash;
    const char *base;
    size_t dirlen;
    char *tmp;
    mode_t mode;
    sigset_t old_mask;
    FILE *fp;
    int fd;
    int e;

    slash = strrchr(path, '/');
    dirlen = slash != NULL ? (size_t)(slash - path) + 1u : 0u; /* keeps the '/' */
    base = path + dirlen;
    if (*base == '\0') {
        stp_posix_priv_error(err, errlen, "%s: names a directory, not a file", path);
        return -1;
    }
    /* "<dir>/.<name>.XXXXXX": same directory (so rename is atomic), hidden,
     * and recognisably the target's if a crash leaves it behind.  It lives
     * in pending_tmp so that a signal handler can remove it. */
    if (dirlen + 1u + strlen(base) + 8u > sizeof pending_tmp) {
        stp_posix_priv_error(err, errlen, "%s: %s", path, strerror(ENAMETOOLONG));
        return -1;
    }
    tmp = pending_tmp;
    memcpy(tmp, path, dirlen);
    tmp[dirlen] = '\0';
    strcat(tmp, ".");
    strcat(tmp, base);
    strcat(tmp, ".XXXXXX");

    mode = target_mode(path);
    block_cleanup_signals(&old_mask);
    install_cleanup();
    fd = mkstemp(tmp);
    pending_armed = fd >= 0;
    (void)sigprocmask(SIG_SETMASK, &old_mask, NULL);
    if (fd < 0) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot create temporary file %s: %s",
                             path, tmp, strerror(e));
        uninstall_cleanup();
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
    block_cleanup_signals(&old_mask);
    if (rename(tmp, path) != 0) {
        e = saved_errno();
        (void)sigprocmask(SIG_SETMASK, &old_mask, NULL);
        stp_posix_priv_error(err, errlen, "%s: cannot rename %s over it: %s",
                             path, tmp, strerror(e));
        goto fail;
    }
    pending_armed = 0;
    uninstall_cleanup();
    (void)sigprocmask(SIG_SETMASK, &old_mask, NULL);
    sync_directory(path, dirlen);
    return 0;

fail:
    block_cleanup_signals(&old_mask);
    (void)unlink(tmp);
    pending_armed = 0;
    uninstall_cleanup();
    (void)sigprocmask(SIG_SETMASK, &old_mask, NULL);
    return -1;
}

int stp_posix_write_file(const char *path, stp_posix_emit_fn emit, void *ctx,
                         char *err, size_t errlen)
{
    struct stat st;
    char *real;
    int via_proc, rc, e;

    if (path == NULL || *path == '\0' || emit == NULL) {
        stp_posix_priv_error(err, errlen, "%s: invalid arguments to the file writer",
                             path != NULL && *path != '\0' ? path : "(no path)");
        return -1;
    }
    if (strcmp(path, "-") == 0)
        return write_stdout(emit, ctx, err, errlen);
    if (stat(path, &st) == 0) {
        if (S_ISDIR(st.st_mode)) {
            stp_posix_priv_error(err, errlen, "%s: is a directory, not a file", path);
            return -1;
        }
        /* a terminal, /dev/null, a pipe: written as it is */
        if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))
            return write_in_place(path, emit, ctx, 0, err, errlen);
        if (!S_ISREG(st.st_mode)) {
            stp_posix_priv_error(err, errlen, "%s: not a regular file, character device or "
                                 "FIFO: refusing to write there", path);
            return -1;
        }
    }
    real = follow_links(path, &via_proc);
    if (real == NULL) {
        e = saved_errno();
        stp_posix_priv_error(err, errlen, "%s: cannot follow the link: %s", path, strerror(e));
        return -1;
    }
    /* /dev/stdout redirected to a file: the shell's descriptor points at
     * that file, which must be written (appended to, as the shell's own
     * descriptor would), not replaced */
    if (via_proc)
        rc = write_in_place(path, emit, ctx, 1, err, errlen);
    else
        rc = replace_atomically(real, emit, ctx, err, errlen);
    free(real);
    return rc;
}
