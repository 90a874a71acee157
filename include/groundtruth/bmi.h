/* The Basic Model Interface (CSDMS BMI 2.0) in C, as groundtruth drives an outside implementation.
 *
 * Written from the BMI 2.0 specification (bmi.readthedocs.io): a struct of function pointers, one
 * per BMI function, each taking the struct itself and returning BMI_SUCCESS or BMI_FAILURE. The
 * member order is the C binding's, so a library built against the CSDMS C header plugs in as is.
 *
 * How groundtruth uses it (docs/external-implementations.md says it in full):
 *   - `groundtruth run --implementation libmine.so[:register_fn]` opens the library, calls
 *     `Bmi *register_fn(Bmi *model)` (default name: register_bmi), which fills the function pointers
 *     (and `data`, the model's own state) and returns `model`.
 *   - initialize(config_file): a text file of `key value` lines the harness writes per case: the
 *     algorithm, the grid (rows, columns, spacing) and every parameter of the algorithm's table.
 *   - The model's output variables must be the algorithm's declared state fields (`groundtruth
 *     list --json`: each algorithm's "fields", names and units), each also an input variable,
 *     on grid 0, a uniform rectilinear grid of shape {rows, columns} and spacing {dy, dx}, of
 *     type "float" / "float32" or "double" / "float64".
 *   - An optional input variable "iteration" (type "int", unit "1") is set to the number of
 *     iterations behind each state the harness loads (a model whose step depends on it, such as
 *     thermal erosion's alternating neighbourhood, declares it).
 *   - update() is one iteration of the algorithm; get_value/set_value copy a whole variable,
 *     row-major, into/from a buffer of get_var_nbytes bytes.
 * Called: initialize, update, finalize, get_output_item_count, get_output_var_names,
 * get_input_item_count, get_input_var_names, get_var_grid, get_var_type, get_var_units,
 * get_var_itemsize, get_var_nbytes, get_grid_rank, get_grid_size, get_grid_shape,
 * get_grid_spacing, get_value, set_value. The rest may be NULL.
 */
#ifndef GROUNDTRUTH_BMI_H
#define GROUNDTRUTH_BMI_H

#ifdef __cplusplus
extern "C" {
#endif

#define BMI_SUCCESS (0)
#define BMI_FAILURE (1)

/* Buffer sizes for the strings a model writes (names, units, types, locations). */
#define BMI_MAX_UNITS_NAME (2048)
#define BMI_MAX_TYPE_NAME (2048)
#define BMI_MAX_COMPONENT_NAME (2048)
#define BMI_MAX_VAR_NAME (2048)
#define BMI_MAX_LOCATION_NAME (2048)

typedef struct Bmi {
  void *data; /* the model's own state */

  /* Initialize, run, finalize */
  int (*initialize)(struct Bmi *self, const char *config_file);
  int (*update)(struct Bmi *self);
  int (*update_until)(struct Bmi *self, double then);
  int (*finalize)(struct Bmi *self);

  /* Exchange items */
  int (*get_component_name)(struct Bmi *self, char *name);
  int (*get_input_item_count)(struct Bmi *self, int *count);
  int (*get_output_item_count)(struct Bmi *self, int *count);
  int (*get_input_var_names)(struct Bmi *self, char **names);
  int (*get_output_var_names)(struct Bmi *self, char **names);

  /* Variable information */
  int (*get_var_grid)(struct Bmi *self, const char *name, int *grid);
  int (*get_var_type)(struct Bmi *self, const char *name, char *type);
  int (*get_var_units)(struct Bmi *self, const char *name, char *units);
  int (*get_var_itemsize)(struct Bmi *self, const char *name, int *size);
  int (*get_var_nbytes)(struct Bmi *self, const char *name, int *nbytes);
  int (*get_var_location)(struct Bmi *self, const char *name, char *location);

  /* Time information */
  int (*get_current_time)(struct Bmi *self, double *time);
  int (*get_start_time)(struct Bmi *self, double *time);
  int (*get_end_time)(struct Bmi *self, double *time);
  int (*get_time_units)(struct Bmi *self, char *units);
  int (*get_time_step)(struct Bmi *self, double *time_step);

  /* Getters */
  int (*get_value)(struct Bmi *self, const char *name, void *dest);
  int (*get_value_ptr)(struct Bmi *self, const char *name, void **dest_ptr);
  int (*get_value_at_indices)(struct Bmi *self, const char *name, void *dest, int *inds, int count);

  /* Setters */
  int (*set_value)(struct Bmi *self, const char *name, void *src);
  int (*set_value_at_indices)(struct Bmi *self, const char *name, int *inds, int count, void *src);

  /* Grid information */
  int (*get_grid_rank)(struct Bmi *self, int grid, int *rank);
  int (*get_grid_size)(struct Bmi *self, int grid, int *size);
  int (*get_grid_type)(struct Bmi *self, int grid, char *type);

  /* Uniform rectilinear */
  int (*get_grid_shape)(struct Bmi *self, int grid, int *shape);
  int (*get_grid_spacing)(struct Bmi *self, int grid, double *spacing);
  int (*get_grid_origin)(struct Bmi *self, int grid, double *origin);

  /* Non-uniform rectilinear, curvilinear */
  int (*get_grid_x)(struct Bmi *self, int grid, double *x);
  int (*get_grid_y)(struct Bmi *self, int grid, double *y);
  int (*get_grid_z)(struct Bmi *self, int grid, double *z);

  /* Unstructured */
  int (*get_grid_node_count)(struct Bmi *self, int grid, int *count);
  int (*get_grid_edge_count)(struct Bmi *self, int grid, int *count);
  int (*get_grid_face_count)(struct Bmi *self, int grid, int *count);
  int (*get_grid_edge_nodes)(struct Bmi *self, int grid, int *edge_nodes);
  int (*get_grid_face_edges)(struct Bmi *self, int grid, int *face_edges);
  int (*get_grid_face_nodes)(struct Bmi *self, int grid, int *face_nodes);
  int (*get_grid_nodes_per_face)(struct Bmi *self, int grid, int *nodes_per_face);
} Bmi;

/* What a registration function looks like: fills `model` and returns it (NULL: refused). */
typedef Bmi *(*BmiRegisterFunction)(Bmi *model);

#ifdef __cplusplus
}
#endif

#endif /* GROUNDTRUTH_BMI_H */
