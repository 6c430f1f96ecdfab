/* The simulated world of the demo robot: a moving ball and two goals seen by a simulated
 * HaViMo2 camera (160x120, colour classes, region growing and gridding), and the data of
 * the reference debug options. Not part of the communication core (footprint excludes it). */
#ifndef SIM_WORLD_H
#define SIM_WORLD_H

#include <stdint.h>
#include "fw_robot.h"

/* HaViMo2 colour classes used by the simulation (documented in README.md). */
enum { CC_UNKNOWN = 0, CC_BALL = 1, CC_FIELD = 2, CC_YELLOW_GOAL = 3, CC_BLUE_GOAL = 4, CC_WHITE = 5 };

#define SIM_FRAME_W 160
#define SIM_FRAME_H 120
#define SIM_GRID_COLS 16
#define SIM_GRID_ROWS 12
#define SIM_IMAGE_W 40
#define SIM_IMAGE_H 30

void sim_world_init(int32_t robot_id);
const fw_option_def *sim_world_options(uint8_t *count);
void sim_world_position(uint32_t now, fumanoid_Position *p);
/* The ball relative to self (mm) at time now; returns its age in seconds (fw_ball_fn). */
float sim_world_ball(uint32_t now, const fumanoid_Position *self, float rel[2]);
/* Colour class of one camera pixel at time now (ms). */
uint8_t sim_world_pixel(uint32_t now, int x, int y);

#endif
