/* SPDX-License-Identifier: MIT */
/*
 * What the emulated panels of tests/spi must show, shared by test_spi and
 * test_spi_cli: the scene's MONO1 render in memory, and the comparison of
 * an emulated panel's glass with it.  Include after <cmocka.h>.
 */
#ifndef STIPPLE_TESTS_SPI_EXPECT_H
#define STIPPLE_TESTS_SPI_EXPECT_H

#include <stdint.h>

#include "scene.h"
#include "spi_sim.h"
#include "stp_posix.h"

/* The scene's MONO1 picture at w x h (default render options, whole
 * frame) into frame; fails the test unless both kinds of pixel are there
 * in quantity (a picture, not a blank). */
void spi_expected_render(const stp_scene *scene, uint32_t w, uint32_t h, stp_posix_frame *frame);

/* Fails the test unless the panel's glass equals want pixel for pixel; a
 * failing glass is saved as $STP_BINARY_DIR/<name>.glass.pbm. */
void spi_assert_glass(spi_sim *sim, const stp_posix_frame *want, const char *name);

#endif
