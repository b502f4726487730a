/* SPDX-License-Identifier: MIT */
/*
 * The stipple command against an emulated SPI panel: `stipple render SCENE
 * --device spi:...` runs as a child process; it inherits umockdev's preload
 * library and UMOCKDEV_DIR from this process (run under umockdev-wrapper),
 * so its open and ioctls of /dev/spidev0.0 reach the Sharp LS013B7DH03
 * emulated here (spi_sim.c).  The glass must then equal, pixel for pixel,
 * the MONO1 render of the same scene in memory, with no protocol violation.
 * A bad controller name must fail with a message naming it and send the
 * panel nothing.
 *
 * Usage: test_spi_cli PATH-TO-STIPPLE (STP_SCENES_DIR: the scenes).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <errno.h>
#include <spawn.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "render_scene.h"
#include "scene.h"
#include "spi_expect.h"
#include "spi_sim.h"
#include "test_scenes.h"
#include "stp_posix.h"

extern char **environ;

static const char *stipple_path;

/* Runs stipple with args (NULL-terminated, without argv[0]); returns its
 * wait status and its stderr in err (NUL-terminated, truncated). */
static int run_stipple(const char *const *args, char *err, size_t errlen)
{
    const char *argv[16];
    posix_spawn_file_actions_t fa;
    int fds[2], status, rc;
    size_t n = 0, got = 0;
    pid_t pid;
    argv[n++] = stipple_path;
    while (*args && n < 15)
        argv[n++] = *args++;
    argv[n] = NULL;
    assert_int_equal(pipe(fds), 0);
    assert_int_equal(posix_spawn_file_actions_init(&fa), 0);
    assert_int_equal(posix_spawn_file_actions_adddup2(&fa, fds[1], 2), 0);
    assert_int_equal(posix_spawn_file_actions_addclose(&fa, fds[0]), 0);
    assert_int_equal(posix_spawn_file_actions_addclose(&fa, fds[1]), 0);
    /* environ: LD_PRELOAD (umockdev-wrapper) and UMOCKDEV_DIR (the testbed) */
    rc = posix_spawn(&pid, stipple_path, &fa, NULL, (char *const *)argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    close(fds[1]);
    if (rc != 0)
        fail_msg("cannot run %s: %s", stipple_path, strerror(rc));
    for (;;) {
        char buf[512];
        ssize_t r = read(fds[0], buf, sizeof buf);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            break;
        if (got + 1 < errlen) {
            size_t k = (size_t)r < errlen - 1 - got ? (size_t)r : errlen - 1 - got;
            memcpy(err + got, buf, k);
            got += k;
        }
    }
    err[got] = '\0';
    close(fds[0]);
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            fail_msg("waitpid: %s", strerror(errno));
    return status;
}

static void test_cli_render_sharp(void **state)
{
    spi_sim *sim = spi_sim_new(SPI_SIM_SHARP, 128, 128, 0);
    stp_posix_frame want;
    char path[1024], err[4096], *v;
    const char *good[] = {"render", path, "--device",
                          "spi:/dev/spidev0.0,controller=sharp-ls013b7dh03", NULL};
    const char *bad[] = {"render", path, "--device", "spi:/dev/spidev0.0,controller=nope", NULL};
    int status;
    (void)state;
    stp_test_scene_path("tetra-s1.nff", path, sizeof path);
    {
        stp_scene scene;
        stp_test_load_scene("tetra-s1.nff", &scene);
        spi_expected_render(&scene, 128, 128, &want);
        stp_scene_free(&scene);
    }

    /* a bad controller: refused before the panel is touched */
    spi_sim_scramble(sim, 7);
    status = run_stipple(bad, err, sizeof err);
    if (!WIFEXITED(status) || WEXITSTATUS(status) == 0)
        fail_msg("bad spec: status 0x%x, stderr: %s", status, err);
    if (!strstr(err, "'nope'"))
        fail_msg("bad spec: stderr does not name 'nope': %s", err);
    g_mutex_lock(&sim->lock);
    assert_int_equal(sim->messages, 0);
    assert_int_equal(sim->transfers, 0);
    assert_int_equal(sim->bytes, 0);
    assert_int_equal(sim->lines_written, 0);
    g_mutex_unlock(&sim->lock);

    /* the scene on the glass, through the command */
    spi_sim_scramble(sim, 99);
    status = run_stipple(good, err, sizeof err);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        fail_msg("stipple render: status 0x%x, stderr: %s", status, err);
    g_mutex_lock(&sim->lock);
    assert_true(sim->messages > 0);
    assert_true(sim->lines_written >= 128);
    assert_int_equal(sim->oversize, 0);
    assert_int_equal(sim->unknown_ioctls, 0);
    assert_true(sim->max_message <= sim->bufsiz);
    g_mutex_unlock(&sim->lock);
    v = spi_sim_violations(sim);
    if (*v)
        fail_msg("protocol violations: %s", v);
    g_free(v);
    spi_assert_glass(sim, &want, "cli-sharp-tetra");

    stp_posix_frame_free(&want);
    spi_sim_free(sim);
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cli_render_sharp),
    };
    if (argc != 2) {
        fprintf(stderr, "usage: %s PATH-TO-STIPPLE\n", argv[0]);
        return 2;
    }
    stipple_path = argv[1];
    return cmocka_run_group_tests(tests, NULL, NULL);
}
