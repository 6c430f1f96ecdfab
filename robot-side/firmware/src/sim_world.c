#include "sim_world.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static int32_t g_id;
static uint32_t g_rng = 12345u;
static uint32_t g_frame;

static float noise(void)
{
    g_rng = g_rng * 1103515245u + 12345u;
    return (float)((g_rng >> 8) & 0xFFFF) / 65535.0f - 0.5f;
}

void sim_world_init(int32_t robot_id)
{
    g_id = robot_id;
    g_rng = 12345u + (uint32_t)robot_id * 7919u;
}

static float secs(uint32_t now) { return (float)now / 1000.0f + (float)g_id * 1.7f; }

void sim_world_position(uint32_t now, fumanoid_Position *p)
{
    float t = secs(now) * 0.2f;
    float base_x = g_id % 3 == 1 ? -4000.0f : (g_id % 3 == 2 ? -2000.0f : 500.0f);
    p->has_x = p->has_y = p->has_theta = true;
    p->x = base_x + 800.0f * sinf(t);
    p->y = 1500.0f * sinf(t * 0.7f + (float)g_id);
    p->theta = fmodf(t * 0.5f, 6.2831853f) - 3.14159265f;
}

/* Ball in field coordinates (mm): a slow ellipse around the centre. */
static void ball_field(uint32_t now, float *x, float *y)
{
    float t = (float)now / 1000.0f * 0.15f;
    *x = 2500.0f * sinf(t);
    *y = 1500.0f * sinf(t * 1.3f);
}

/* A field point (mm) in the robot's own frame. */
static void to_robot(const fumanoid_Position *me, float x, float y, float rel[2])
{
    float c = cosf(-me->theta), s = sinf(-me->theta), dx = x - me->x, dy = y - me->y;
    rel[0] = c * dx - s * dy;
    rel[1] = s * dx + c * dy;
}

float sim_world_ball(uint32_t now, const fumanoid_Position *self, float rel[2])
{
    float bx, by;
    ball_field(now, &bx, &by);
    to_robot(self, bx, by, rel);
    return 0.1f; /* the simulated camera always sees it, a frame ago */
}

/* Camera scene at time now: ball centre/radius and the two goal rectangles in pixels. */
typedef struct { int bx, by, br; int yg[4]; int bg[4]; } scene;

static void scene_at(uint32_t now, scene *s)
{
    float t = secs(now);
    int pan = (int)(25.0f * sinf(t * 0.4f));
    s->bx = 80 + (int)(55.0f * sinf(t * 0.9f));
    s->by = 75 + (int)(30.0f * sinf(t * 1.3f));
    s->br = 6 + (int)(3.0f * (1.0f + sinf(t * 0.5f)));
    s->yg[0] = 10 + pan; s->yg[1] = 20; s->yg[2] = 50 + pan; s->yg[3] = 45;
    s->bg[0] = 105 + pan; s->bg[1] = 22; s->bg[2] = 150 + pan; s->bg[3] = 46;
}

static int inside(const int r[4], int x, int y) { return x >= r[0] && x <= r[2] && y >= r[1] && y <= r[3]; }

static uint8_t pixel(const scene *s, int x, int y)
{
    int dx = x - s->bx, dy = y - s->by;
    if (dx * dx + dy * dy <= s->br * s->br) return CC_BALL;
    if (inside(s->yg, x, y)) return CC_YELLOW_GOAL;
    if (inside(s->bg, x, y)) return CC_BLUE_GOAL;
    if (y < 40) return CC_UNKNOWN;             /* above the horizon */
    if (y == 90 || y == 91 || (x + y / 3) % 53 == 0) return CC_WHITE; /* field lines */
    return CC_FIELD;
}

uint8_t sim_world_pixel(uint32_t now, int x, int y)
{
    scene s;
    scene_at(now, &s);
    return pixel(&s, x, y);
}

static int clampi(int v, int lo, int hi) { return v < lo ? lo : (v > hi ? hi : v); }

static void set_str(char *dst, size_t cap, const char *src)
{
    strncpy(dst, src, cap - 1);
    dst[cap - 1] = '\0';
}

static bool produce_text(uint32_t now, fw_outgoing *out)
{
    fumanoid_DebugText *m = &out->m.text;
    float bx, by;
    static const char *const lines[] = {"searching ball", "ball seen, approaching", "aligning to goal",
                                        "kicking", "ball lost, turning head"};
    ball_field(now, &bx, &by);
    *m = (fumanoid_DebugText)fumanoid_DebugText_init_zero;
    out->type = &fumanoid_debugText;
    set_str(m->option, sizeof m->option, "demo.text");
    m->has_text = true;
    snprintf(m->text, sizeof m->text, "[%lu] robot %ld: %s; ball at (%.0f, %.0f) mm",
             (unsigned long)(g_frame++), (long)g_id, lines[(now / 2000u) % 5u], bx, by);
    m->has_timestamp = true;
    m->timestamp = now;
    return true;
}

static bool produce_plot(uint32_t now, fw_outgoing *out)
{
    fumanoid_DebugPlot *m = &out->m.plot;
    float t = secs(now);
    static const char *const names[] = {"sin", "cos", "noise", "ballDistance", "gyroX"};
    float values[5];
    int i;
    values[0] = sinf(t);
    values[1] = cosf(t * 0.5f) * 2.0f;
    values[2] = noise();
    values[3] = 1.5f + sinf(t * 0.3f) + 0.1f * noise();
    values[4] = 0.2f * sinf(t * 7.0f) + 0.05f * noise();
    *m = (fumanoid_DebugPlot)fumanoid_DebugPlot_init_zero;
    out->type = &fumanoid_debugPlot;
    set_str(m->option, sizeof m->option, "demo.plotter");
    m->has_timestamp = true;
    m->timestamp = now;
    for (i = 0; i < 5; i++) {
        set_str(m->samples[i].series, sizeof m->samples[i].series, names[i]);
        m->samples[i].has_value = true;
        m->samples[i].value = values[i];
    }
    m->samples_count = 5;
    return true;
}

static bool produce_table(uint32_t now, fw_outgoing *out)
{
    fumanoid_DebugTable *m = &out->m.table;
    static const char *const header[] = {"servo", "position", "load", "temp C"};
    static const char *const joints[] = {"head pan", "head tilt", "l hip", "r hip", "l knee", "r knee"};
    float t = secs(now);
    int i;
    *m = (fumanoid_DebugTable)fumanoid_DebugTable_init_zero;
    out->type = &fumanoid_debugTable;
    set_str(m->option, sizeof m->option, "demo.table");
    for (i = 0; i < 4; i++) set_str(m->header[i], sizeof m->header[i], header[i]);
    m->header_count = 4;
    for (i = 0; i < 6; i++) {
        fumanoid_TableRow *r = &m->rows[i];
        set_str(r->cells[0], sizeof r->cells[0], joints[i]);
        snprintf(r->cells[1], sizeof r->cells[1], "%d", 512 + (int)(200.0f * sinf(t + (float)i)));
        snprintf(r->cells[2], sizeof r->cells[2], "%d%%", (int)(30.0f + 20.0f * sinf(t * 0.7f + (float)i)));
        snprintf(r->cells[3], sizeof r->cells[3], "%d", 38 + i + (int)(now / 60000u) % 10);
        r->cells_count = 4;
    }
    m->rows_count = 6;
    return true;
}

static bool produce_image(uint32_t now, fw_outgoing *out)
{
    static const uint8_t gray[] = {40, 230, 90, 200, 120, 255};
    fumanoid_DebugImage *m = &out->m.image;
    scene s;
    int x, y;
    scene_at(now, &s);
    *m = (fumanoid_DebugImage)fumanoid_DebugImage_init_zero;
    out->type = &fumanoid_debugImage;
    set_str(m->option, sizeof m->option, "demo.image");
    m->has_width = m->has_height = m->has_format = true;
    m->width = SIM_IMAGE_W;
    m->height = SIM_IMAGE_H;
    m->format = fumanoid_ImageFormat_GRAY8;
    for (y = 0; y < SIM_IMAGE_H; y++) {
        for (x = 0; x < SIM_IMAGE_W; x++) {
            uint8_t c = pixel(&s, x * 4 + 2, y * 4 + 2);
            m->data.bytes[y * SIM_IMAGE_W + x] = gray[c];
        }
    }
    m->has_data = true;
    m->data.size = SIM_IMAGE_W * SIM_IMAGE_H;
    return true;
}

static void object(fumanoid_RelativeObject *o, const char *label, float x, float y, uint32_t cc)
{
    o->has_label = true;
    set_str(o->label, sizeof o->label, label);
    o->has_x = o->has_y = o->has_colorClass = true;
    o->x = x;
    o->y = y;
    o->colorClass = cc;
}

static bool produce_relative(uint32_t now, fw_outgoing *out)
{
    fumanoid_RelativePositions *m = &out->m.relative;
    fumanoid_Position me;
    float rel[2];
    sim_world_position(robot_motion_clock(), &me);
    *m = (fumanoid_RelativePositions)fumanoid_RelativePositions_init_zero;
    out->type = &fumanoid_relativePositions;
    set_str(m->option, sizeof m->option, "demo.relative");
    (void)sim_world_ball(now, &me, rel);
    object(&m->objects[0], "ball", rel[0], rel[1], CC_BALL);
    to_robot(&me, 4500.0f, 0.0f, rel);
    object(&m->objects[1], "yellowGoal", rel[0], rel[1], CC_YELLOW_GOAL);
    to_robot(&me, -4500.0f, 0.0f, rel);
    object(&m->objects[2], "blueGoal", rel[0], rel[1], CC_BLUE_GOAL);
    m->objects_count = 3;
    return true;
}

static bool produce_field(uint32_t now, fw_outgoing *out)
{
    fumanoid_FieldObjects *m = &out->m.field;
    fumanoid_Position me;
    float bx, by;
    sim_world_position(robot_motion_clock(), &me);
    ball_field(now, &bx, &by);
    *m = (fumanoid_FieldObjects)fumanoid_FieldObjects_init_zero;
    out->type = &fumanoid_fieldObjects;
    set_str(m->option, sizeof m->option, "demo.field");
    object(&m->objects[0], "ball", bx + 30.0f * noise(), by + 30.0f * noise(), CC_BALL);
    object(&m->objects[1], "self", me.x, me.y, 0);
    m->objects_count = 2;
    return true;
}

static void region(fumanoid_Region *r, uint32_t cc, int x1, int y1, int x2, int y2)
{
    r->has_colorClass = r->has_x1 = r->has_y1 = r->has_x2 = r->has_y2 = r->has_pixels = true;
    r->colorClass = cc;
    r->x1 = clampi(x1, 0, SIM_FRAME_W - 1);
    r->y1 = clampi(y1, 0, SIM_FRAME_H - 1);
    r->x2 = clampi(x2, 0, SIM_FRAME_W - 1);
    r->y2 = clampi(y2, 0, SIM_FRAME_H - 1);
    r->pixels = (uint32_t)((r->x2 - r->x1 + 1) * (r->y2 - r->y1 + 1));
}

static bool produce_regions(uint32_t now, fw_outgoing *out)
{
    fumanoid_RegionGrowing *m = &out->m.regions;
    scene s;
    scene_at(now, &s);
    *m = (fumanoid_RegionGrowing)fumanoid_RegionGrowing_init_zero;
    out->type = &fumanoid_regionGrowing;
    set_str(m->option, sizeof m->option, "havimo.region");
    m->has_frameWidth = m->has_frameHeight = m->has_timestamp = true;
    m->frameWidth = SIM_FRAME_W;
    m->frameHeight = SIM_FRAME_H;
    m->timestamp = now;
    region(&m->regions[0], CC_BALL, s.bx - s.br, s.by - s.br, s.bx + s.br, s.by + s.br);
    region(&m->regions[1], CC_YELLOW_GOAL, s.yg[0], s.yg[1], s.yg[2], s.yg[3]);
    region(&m->regions[2], CC_BLUE_GOAL, s.bg[0], s.bg[1], s.bg[2], s.bg[3]);
    m->regions_count = 3;
    /* Drop regions that left the frame completely. */
    {
        pb_size_t i, k = 0;
        for (i = 0; i < m->regions_count; i++) {
            if (m->regions[i].x2 > m->regions[i].x1 && m->regions[i].y2 > m->regions[i].y1) m->regions[k++] = m->regions[i];
        }
        m->regions_count = k;
    }
    return true;
}

static bool produce_grid(uint32_t now, fw_outgoing *out)
{
    fumanoid_Grid *m = &out->m.grid;
    scene s;
    int cx, cy;
    scene_at(now, &s);
    *m = (fumanoid_Grid)fumanoid_Grid_init_zero;
    out->type = &fumanoid_grid;
    set_str(m->option, sizeof m->option, "havimo.grid");
    m->has_columns = m->has_rows = m->has_frameWidth = m->has_frameHeight = m->has_cells = true;
    m->columns = SIM_GRID_COLS;
    m->rows = SIM_GRID_ROWS;
    m->frameWidth = SIM_FRAME_W;
    m->frameHeight = SIM_FRAME_H;
    for (cy = 0; cy < SIM_GRID_ROWS; cy++) {
        for (cx = 0; cx < SIM_GRID_COLS; cx++) {
            /* The cell's class is the majority over a 5x5 sample of its 10x10 pixels. */
            int counts[6] = {0, 0, 0, 0, 0, 0}, best = 0, sx, sy, k;
            for (sy = 0; sy < 10; sy += 2)
                for (sx = 0; sx < 10; sx += 2) counts[pixel(&s, cx * 10 + sx, cy * 10 + sy)]++;
            for (k = 1; k < 6; k++)
                if (counts[k] > counts[best] || (k == CC_BALL && counts[k] > 0)) best = k;
            m->cells.bytes[cy * SIM_GRID_COLS + cx] = (uint8_t)best;
        }
    }
    m->cells.size = SIM_GRID_COLS * SIM_GRID_ROWS;
    return true;
}

static const fw_option_def k_options[] = {
    {"demo.text", "behaviour log lines", fumanoid_DebugKind_TEXT, produce_text},
    {"demo.plotter", "sine, noise, ball distance, gyro", fumanoid_DebugKind_PLOT, produce_plot},
    {"demo.table", "servo positions, load, temperature", fumanoid_DebugKind_TABLE, produce_table},
    {"demo.image", "camera frame 40x30 GRAY8", fumanoid_DebugKind_IMAGE, produce_image},
    {"demo.relative", "ball and goals relative to the robot", fumanoid_DebugKind_RELATIVE_POSITIONS, produce_relative},
    {"demo.field", "ball and robot in field coordinates", fumanoid_DebugKind_FIELD, produce_field},
    {"havimo.region", "HaViMo2 region growing 160x120", fumanoid_DebugKind_REGION_GROWING, produce_regions},
    {"havimo.grid", "HaViMo2 gridding 16x12 cells", fumanoid_DebugKind_GRID, produce_grid},
};

const fw_option_def *sim_world_options(uint8_t *count)
{
    *count = (uint8_t)(sizeof k_options / sizeof k_options[0]);
    return k_options;
}
