/* Outside implementations that break the rules, for the tests of --implementation
 * (tests/external_cli_test.cpp): the correct example of examples/thermal_bmi/ with one member
 * replaced, each variant behind its own registration function in one library. The crashes abort
 * (as a failed assert does): a segmentation fault would be caught and reported by AddressSanitizer
 * in the sanitizer build instead of killing the process by its signal. */
#include <stdlib.h>
#include <unistd.h>

#include "../../examples/thermal_bmi/thermal_bmi.c"

/* Calls its variable "height" where erosion.thermal declares "terrain". */
static int named_height(Bmi *self, char **names) {
  (void)self;
  snprintf(names[0], BMI_MAX_VAR_NAME, "height");
  return BMI_SUCCESS;
}

Bmi *register_wrong_name(Bmi *model) {
  register_bmi_thermal(model);
  model->get_output_var_names = named_height;
  return model;
}

/* Heights in feet. */
static int in_feet(Bmi *self, const char *name, char *units) {
  (void)self;
  snprintf(units, BMI_MAX_UNITS_NAME, is_terrain(name) ? "ft" : "1");
  return BMI_SUCCESS;
}

Bmi *register_wrong_units(Bmi *model) {
  register_bmi_thermal(model);
  model->get_var_units = in_feet;
  return model;
}

/* Its grid transposed: {columns, rows}, and one row more. */
static int transposed(Bmi *self, int grid, int *shape) {
  const Thermal *t = thermal(self);
  if (grid == 0) { shape[0] = t->columns; shape[1] = t->rows + 1; }
  else shape[0] = 1;
  return BMI_SUCCESS;
}

Bmi *register_wrong_shape(Bmi *model) {
  register_bmi_thermal(model);
  model->get_grid_shape = transposed;
  return model;
}

/* Leaves get_value NULL. */
Bmi *register_no_getter(Bmi *model) {
  register_bmi_thermal(model);
  model->get_value = NULL;
  return model;
}

/* Its step aborts after 3 updates (past initialisation, inside the run). */
static int crashing_update(Bmi *self) {
  if (thermal(self)->iteration >= 3) abort();
  return update(self);
}

Bmi *register_crash(Bmi *model) {
  register_bmi_thermal(model);
  model->update = crashing_update;
  return model;
}

/* Its step never returns after 3 updates. */
static int hanging_update(Bmi *self) {
  while (thermal(self)->iteration >= 3) sleep(1);
  return update(self);
}

Bmi *register_hang(Bmi *model) {
  register_bmi_thermal(model);
  model->update = hanging_update;
  return model;
}

/* Aborts inside initialize. */
static int crashing_initialize(Bmi *self, const char *config_file) {
  (void)self;
  (void)config_file;
  abort();
}

Bmi *register_crash_in_initialize(Bmi *model) {
  register_bmi_thermal(model);
  model->initialize = crashing_initialize;
  return model;
}
