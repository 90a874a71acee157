/* An outside implementation of erosion.thermal (seed 000, Hydra, §4.4.3, Algorithms 9-11) behind
 * the C Basic Model Interface, as a user would write one to have groundtruth grade it:
 *
 *   groundtruth run --algorithm erosion.thermal --input datasets/real/volcano.json \
 *       --implementation build/release/examples/libthermal_bmi.so:register_bmi_thermal
 *
 * Written from the digest (docs of seed 000, §4.6), not from groundtruth's twins: each iteration
 * computes, per cell and pipe (4 neighbours: cardinal on even iterations, diagonal on odd ones for
 * the alternating neighbourhood), the excess over the talus limit T·l (T = tan α), a request per
 * pipe scaled by f_s = strength/2, then moves the smaller of two opposite requests along each pipe.
 * Heights in float (the state variable "terrain", metres), a uniform grid of the config's spacing.
 * Cells outside the grid or holding NaN (no data) take no part.
 *
 * Built twice by CMake: libthermal_bmi.so, and libthermal_bmi_seeded_bug.so with
 * THERMAL_BMI_SEEDED_BUG, whose diagonal pipes are as long as the x pipes (no √2): a subtle bug
 * that only the odd (diagonal) iterations show.
 *
 * Limits: physical heights only (normalised = false), as a small example; initialize refuses the rest.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "groundtruth/bmi.h"

typedef struct {
  int rows, columns;
  double spacing_x, spacing_y;
  float talus_limit_cardinal[4]; /* T·l per pipe, pipes in the order of cardinal_pipes */
  float talus_limit_diagonal;
  float request_factor; /* f_s = strength / 2 */
  int neighbourhood;    /* 0 cardinal, 1 diagonal, 2 alternating */
  int iteration;        /* iterations behind the state */
  float *terrain, *next, *requests;
} Thermal;

static const int cardinal_pipes[4][2] = {{-1, 0}, {0, 1}, {1, 0}, {0, -1}};
static const int diagonal_pipes[4][2] = {{-1, -1}, {-1, 1}, {1, 1}, {1, -1}};

static Thermal *thermal(Bmi *self) { return (Thermal *)self->data; }

/* --- the algorithm ---------------------------------------------------------------------------- */

static int open_pipe(const Thermal *t, int x, int y, int dx, int dy) {
  const int nx = x + dx, ny = y + dy;
  return nx >= 0 && ny >= 0 && nx < t->columns && ny < t->rows && !isnan(t->terrain[ny * t->columns + nx]);
}

static void cell_requests(const Thermal *t, int x, int y, const int (*pipes)[2], const float *limit, float *request) {
  const float height = t->terrain[y * t->columns + x];
  float demand[4] = {0, 0, 0, 0}, supply[4] = {0, 0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    if (!open_pipe(t, x, y, pipes[k][0], pipes[k][1])) continue;
    const float difference = t->terrain[(y + pipes[k][1]) * t->columns + x + pipes[k][0]] - height;
    if (difference > limit[k]) demand[k] = difference - limit[k];
    else if (difference < -limit[k]) supply[k] = difference + limit[k];
  }
  const float largest_demand = fmaxf(fmaxf(demand[0], demand[1]), fmaxf(demand[2], demand[3]));
  const float largest_supply = fminf(fminf(supply[0], supply[1]), fminf(supply[2], supply[3]));
  const float demand_total = demand[0] + demand[1] + demand[2] + demand[3];
  const float supply_total = supply[0] + supply[1] + supply[2] + supply[3];
  const float demand_share =
      demand_total > 0.0f ? fminf(fmaxf(t->request_factor * largest_demand / demand_total, 0.0f), 1.0f) : 0.0f;
  const float supply_share =
      supply_total < 0.0f ? fminf(fmaxf(t->request_factor * largest_supply / supply_total, 0.0f), 1.0f) : 0.0f;
  for (int k = 0; k < 4; ++k) request[k] = supply[k] * supply_share + demand[k] * demand_share;
}

static void iterate(Thermal *t) {
  const int cardinal = t->neighbourhood == 0 || (t->neighbourhood == 2 && t->iteration % 2 == 0);
  const int (*pipes)[2] = cardinal ? cardinal_pipes : diagonal_pipes;
  float limit[4];
  for (int k = 0; k < 4; ++k) limit[k] = cardinal ? t->talus_limit_cardinal[k] : t->talus_limit_diagonal;
  for (int y = 0; y < t->rows; ++y)
    for (int x = 0; x < t->columns; ++x) {
      float *request = t->requests + 4 * (y * t->columns + x);
      if (isnan(t->terrain[y * t->columns + x])) memset(request, 0, 4 * sizeof(float));
      else cell_requests(t, x, y, pipes, limit, request);
    }
  for (int y = 0; y < t->rows; ++y)
    for (int x = 0; x < t->columns; ++x) {
      const int cell = y * t->columns + x;
      float height = t->terrain[cell];
      if (!isnan(height)) {
        for (int k = 0; k < 4; ++k) {
          if (!open_pipe(t, x, y, pipes[k][0], pipes[k][1])) continue;
          const float mine = t->requests[4 * cell + k];
          const float theirs = t->requests[4 * ((y + pipes[k][1]) * t->columns + x + pipes[k][0]) + (k + 2) % 4];
          if (theirs < 0.0f && mine > 0.0f) height = height + fminf(-theirs, mine);
          else if (theirs > 0.0f && mine < 0.0f) height = height - fminf(theirs, -mine);
        }
      }
      t->next[cell] = height;
    }
  float *swap = t->terrain;
  t->terrain = t->next;
  t->next = swap;
  ++t->iteration;
}

/* --- the config: `key value` lines ------------------------------------------------------------- */

static int read_config(Thermal *t, const char *path) {
  FILE *file = fopen(path, "r");
  if (!file) return BMI_FAILURE;
  char key[256], value[256];
  double talus_angle = 45.0, strength = 1.0;
  char neighbourhood[256] = "alternating", normalised[256] = "false";
  char line[1024];
  while (fgets(line, sizeof line, file)) {
    if (line[0] == '#' || sscanf(line, "%255s %255s", key, value) != 2) continue;
    if (!strcmp(key, "rows")) t->rows = atoi(value);
    else if (!strcmp(key, "columns")) t->columns = atoi(value);
    else if (!strcmp(key, "spacing_x")) t->spacing_x = atof(value);
    else if (!strcmp(key, "spacing_y")) t->spacing_y = atof(value);
    else if (!strcmp(key, "talus_angle")) talus_angle = atof(value);
    else if (!strcmp(key, "strength")) strength = atof(value);
    else if (!strcmp(key, "neighbourhood")) snprintf(neighbourhood, sizeof neighbourhood, "%s", value);
    else if (!strcmp(key, "normalised")) snprintf(normalised, sizeof normalised, "%s", value);
  }
  fclose(file);
  if (t->rows < 1 || t->columns < 1 || strcmp(normalised, "false") != 0) return BMI_FAILURE;
  t->neighbourhood = !strcmp(neighbourhood, "cardinal") ? 0 : !strcmp(neighbourhood, "diagonal") ? 1 : 2;
  const double slope = tan(talus_angle * M_PI / 180.0);
#ifdef THERMAL_BMI_SEEDED_BUG
  const double diagonal = t->spacing_x;
#else
  const double diagonal = hypot(t->spacing_x, t->spacing_y);
#endif
  for (int k = 0; k < 4; ++k) t->talus_limit_cardinal[k] = (float)(slope * (k % 2 == 0 ? t->spacing_x : t->spacing_y));
  t->talus_limit_diagonal = (float)(slope * diagonal);
  t->request_factor = (float)(strength * 0.5);
  return BMI_SUCCESS;
}

/* --- the Basic Model Interface ----------------------------------------------------------------- */

static size_t cells(const Thermal *t) { return (size_t)t->rows * (size_t)t->columns; }
static int is_terrain(const char *name) { return !strcmp(name, "terrain"); }
static int is_iteration(const char *name) { return !strcmp(name, "iteration"); }

static int initialize(Bmi *self, const char *config_file) {
  Thermal *t = calloc(1, sizeof(Thermal));
  if (!t) return BMI_FAILURE;
  self->data = t;
  if (read_config(t, config_file) != BMI_SUCCESS) return BMI_FAILURE;
  t->terrain = calloc(cells(t), sizeof(float));
  t->next = calloc(cells(t), sizeof(float));
  t->requests = calloc(4 * cells(t), sizeof(float));
  return t->terrain && t->next && t->requests ? BMI_SUCCESS : BMI_FAILURE;
}

static int update(Bmi *self) {
  iterate(thermal(self));
  return BMI_SUCCESS;
}

static int finalize(Bmi *self) {
  Thermal *t = thermal(self);
  if (t) {
    free(t->terrain);
    free(t->next);
    free(t->requests);
    free(t);
  }
  self->data = NULL;
  return BMI_SUCCESS;
}

static int get_component_name(Bmi *self, char *name) {
  (void)self;
  snprintf(name, BMI_MAX_COMPONENT_NAME, "thermal erosion (Hydra), C example");
  return BMI_SUCCESS;
}

static int count_one(Bmi *self, int *count) { (void)self; *count = 1; return BMI_SUCCESS; }
static int count_two(Bmi *self, int *count) { (void)self; *count = 2; return BMI_SUCCESS; }

static int output_names(Bmi *self, char **names) {
  (void)self;
  snprintf(names[0], BMI_MAX_VAR_NAME, "terrain");
  return BMI_SUCCESS;
}

static int input_names(Bmi *self, char **names) {
  (void)self;
  snprintf(names[0], BMI_MAX_VAR_NAME, "terrain");
  snprintf(names[1], BMI_MAX_VAR_NAME, "iteration");
  return BMI_SUCCESS;
}

static int var_grid(Bmi *self, const char *name, int *grid) {
  (void)self;
  if (!is_terrain(name) && !is_iteration(name)) return BMI_FAILURE;
  *grid = is_terrain(name) ? 0 : 1;
  return BMI_SUCCESS;
}

static int var_type(Bmi *self, const char *name, char *type) {
  (void)self;
  if (!is_terrain(name) && !is_iteration(name)) return BMI_FAILURE;
  snprintf(type, BMI_MAX_TYPE_NAME, is_terrain(name) ? "float" : "int");
  return BMI_SUCCESS;
}

static int var_units(Bmi *self, const char *name, char *units) {
  (void)self;
  if (!is_terrain(name) && !is_iteration(name)) return BMI_FAILURE;
  snprintf(units, BMI_MAX_UNITS_NAME, is_terrain(name) ? "m" : "1");
  return BMI_SUCCESS;
}

static int var_itemsize(Bmi *self, const char *name, int *size) {
  (void)self;
  if (!is_terrain(name) && !is_iteration(name)) return BMI_FAILURE;
  *size = is_terrain(name) ? (int)sizeof(float) : (int)sizeof(int);
  return BMI_SUCCESS;
}

static int var_nbytes(Bmi *self, const char *name, int *nbytes) {
  if (!is_terrain(name) && !is_iteration(name)) return BMI_FAILURE;
  *nbytes = is_terrain(name) ? (int)(cells(thermal(self)) * sizeof(float)) : (int)sizeof(int);
  return BMI_SUCCESS;
}

static int time_step(Bmi *self, double *step) { (void)self; *step = 1.0; return BMI_SUCCESS; }

static int get_value(Bmi *self, const char *name, void *dest) {
  Thermal *t = thermal(self);
  if (is_terrain(name)) memcpy(dest, t->terrain, cells(t) * sizeof(float));
  else if (is_iteration(name)) memcpy(dest, &t->iteration, sizeof(int));
  else return BMI_FAILURE;
  return BMI_SUCCESS;
}

static int set_value(Bmi *self, const char *name, void *src) {
  Thermal *t = thermal(self);
  if (is_terrain(name)) memcpy(t->terrain, src, cells(t) * sizeof(float));
  else if (is_iteration(name)) memcpy(&t->iteration, src, sizeof(int));
  else return BMI_FAILURE;
  return BMI_SUCCESS;
}

static int grid_rank(Bmi *self, int grid, int *rank) { (void)self; *rank = grid == 0 ? 2 : 1; return BMI_SUCCESS; }

static int grid_size(Bmi *self, int grid, int *size) {
  *size = grid == 0 ? (int)cells(thermal(self)) : 1;
  return BMI_SUCCESS;
}

static int grid_shape(Bmi *self, int grid, int *shape) {
  const Thermal *t = thermal(self);
  if (grid == 0) { shape[0] = t->rows; shape[1] = t->columns; }
  else shape[0] = 1;
  return BMI_SUCCESS;
}

static int grid_spacing(Bmi *self, int grid, double *spacing) {
  const Thermal *t = thermal(self);
  if (grid == 0) { spacing[0] = t->spacing_y; spacing[1] = t->spacing_x; }
  else spacing[0] = 1.0;
  return BMI_SUCCESS;
}

Bmi *register_bmi_thermal(Bmi *model) {
  model->data = NULL;
  model->initialize = initialize;
  model->update = update;
  model->finalize = finalize;
  model->get_component_name = get_component_name;
  model->get_input_item_count = count_two;
  model->get_output_item_count = count_one;
  model->get_input_var_names = input_names;
  model->get_output_var_names = output_names;
  model->get_var_grid = var_grid;
  model->get_var_type = var_type;
  model->get_var_units = var_units;
  model->get_var_itemsize = var_itemsize;
  model->get_var_nbytes = var_nbytes;
  model->get_time_step = time_step;
  model->get_value = get_value;
  model->set_value = set_value;
  model->get_grid_rank = grid_rank;
  model->get_grid_size = grid_size;
  model->get_grid_shape = grid_shape;
  model->get_grid_spacing = grid_spacing;
  return model;
}

/* The name groundtruth looks for when --implementation names no function. */
Bmi *register_bmi(Bmi *model) { return register_bmi_thermal(model); }
