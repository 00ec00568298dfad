/* Conformance harness in C99 (docs/conformance.md): reads the vectors.csv that
 * `dspbr conformance generate` writes, calls the renderer's eval function for every vector and
 * writes the results file that `dspbr conformance check` judges:
 *
 *   conformance_harness VECTORS.csv RESULTS.csv
 *   dspbr conformance check VECTORS.json RESULTS.csv --out REPORT
 *
 * The renderer plugs in through one function (renderer.h): link your own renderer_eval instead of
 * reference_renderer.cpp (the reference BSDF, used here so that the example passes), or, built
 * with -DRENDERER_BATCH, renderer_eval_batch: all vectors of one material in one call (arrays in,
 * arrays out). A GLSL or
 * HLSL implementation runs through `dspbr conformance run --glsl/--hlsl` instead. A vector the
 * renderer does not support gets no line (NOT SUPPLIED), a pdf it does not compute an empty field.
 * Exit status 0, or 2 with one line on stderr naming the file and the line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "renderer.h"

enum { kMaxLine = 1 << 16, kMaxFields = 32, kMaxBatch = 4096 };

/* Splits one CSV line into fields in place (RFC 4180: quoted fields with doubled quotes). */
static int split_csv(char* line, char** fields) {
  int n = 0;
  char* p = line;
  for (;;) {
    if (n == kMaxFields) return -1;
    if (*p == '"') {
      char *out = ++p, *start = p;
      for (;;) {
        if (*p == '\0') return -1;
        if (*p == '"') {
          if (p[1] == '"') { *out++ = '"'; p += 2; continue; }
          ++p;
          break;
        }
        *out++ = *p++;
      }
      fields[n++] = start;
      if (*p != ',' && *p != '\0') return -1;
      *out = '\0';
    } else {
      fields[n++] = p;
      while (*p != ',' && *p != '\0') ++p;
    }
    if (*p == '\0') return n;
    *p++ = '\0';
  }
}

static int parse_numbers(char** fields, double* out, int count) {
  for (int i = 0; i < count; ++i) {
    char* end = NULL;
    out[i] = strtod(fields[i], &end);
    if (end == fields[i] || *end != '\0') return 0;
  }
  return 1;
}

/* One CSV field, quoted (RFC 4180: a quote inside doubled), so that an id with a comma stays one. */
static void write_csv_field(FILE* out, const char* s) {
  fputc('"', out);
  for (; *s; ++s) {
    if (*s == '"') fputc('"', out);
    fputc(*s, out);
  }
  fputc('"', out);
}

/* The vectors of one material (consecutive lines with the same material and options), evaluated
 * together: by one renderer_eval_batch call when built with -DRENDERER_BATCH, else one
 * renderer_eval per vector. */
typedef struct {
  char* id;
  double vl[6];
} Row;
static Row rows[kMaxBatch];
static int row_count = 0;
static char* group_material = NULL;
static char* group_options = NULL;

static char* copy_text(const char* s) {
  char* c = malloc(strlen(s) + 1);
  if (!c) { fprintf(stderr, "out of memory\n"); exit(2); }
  return strcpy(c, s);
}

/* Writes the group's results; 0 when the renderer failed on one (named on stderr). */
static int flush_group(FILE* out, const char* path, long* written) {
  static double f_cos[3 * kMaxBatch], pdf[kMaxBatch];
  static int status[kMaxBatch];
  for (int i = 0; i < row_count; ++i) pdf[i] = NAN;
#ifdef RENDERER_BATCH
  static double v[3 * kMaxBatch], l[3 * kMaxBatch];
  for (int i = 0; i < row_count; ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = rows[i].vl[k], l[3 * i + k] = rows[i].vl[3 + k];
  const int batch = row_count > 0 ? renderer_eval_batch(group_material, group_options, row_count, v, l, f_cos, pdf)
                                  : RENDERER_OK;
  for (int i = 0; i < row_count; ++i) status[i] = batch;
#else
  for (int i = 0; i < row_count; ++i)
    status[i] = renderer_eval(group_material, group_options, rows[i].vl, rows[i].vl + 3, f_cos + 3 * i, pdf + i);
#endif
  int ok = 1;
  for (int i = 0; i < row_count; ++i) {
    if (ok && status[i] != RENDERER_OK && status[i] != RENDERER_UNSUPPORTED) {
      fprintf(stderr, "%s: id '%s': the renderer cannot evaluate this material\n", path, rows[i].id);
      ok = 0;
    }
    if (ok && status[i] == RENDERER_OK) { /* RENDERER_UNSUPPORTED: no line, NOT SUPPLIED */
      write_csv_field(out, rows[i].id);
      fprintf(out, ",%.17g,%.17g,%.17g,", f_cos[3 * i], f_cos[3 * i + 1], f_cos[3 * i + 2]);
      if (!isnan(pdf[i])) fprintf(out, "%.17g", pdf[i]); /* an empty field: not supplied */
      fputc('\n', out);
      ++*written;
    }
    free(rows[i].id);
  }
  row_count = 0;
  return ok;
}

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s VECTORS.csv RESULTS.csv\n", argv[0]);
    return 2;
  }
  FILE* in = fopen(argv[1], "rb");
  if (!in) { fprintf(stderr, "%s: cannot be read\n", argv[1]); return 2; }
  FILE* out = fopen(argv[2], "wb");
  if (!out) { fprintf(stderr, "%s: cannot be written\n", argv[2]); fclose(in); return 2; }
  static char line[kMaxLine];
  char* f[kMaxFields];
  long number = 0, written = 0;
  /* Columns of vectors.csv: id,group,components,material,options,v_x,v_y,v_z,l_x,l_y,l_z,... */
  fprintf(out, "id,f_cos_r,f_cos_g,f_cos_b,pdf\n");
  while (fgets(line, sizeof line, in)) {
    ++number;
    size_t len = strlen(line);
    while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r')) line[--len] = '\0';
    if (number == 1) {
      static const char kHeader[] = "id,group,components,material,options,v_x,v_y,v_z,l_x,l_y,l_z,";
      if (strncmp(line, kHeader, sizeof kHeader - 1) != 0) {
        fprintf(stderr, "%s: line 1: not a conformance vectors.csv header\n", argv[1]);
        return 2;
      }
      continue;
    }
    if (len == 0) continue;
    Row r;
    if (split_csv(line, f) < 11 || !parse_numbers(f + 5, r.vl, 6)) {
      fprintf(stderr, "%s: line %ld: malformed vector\n", argv[1], number);
      return 2;
    }
    const int same = group_material && strcmp(group_material, f[3]) == 0 && strcmp(group_options, f[4]) == 0;
    if (!same || row_count == kMaxBatch) {
      if (!flush_group(out, argv[1], &written)) return 2;
      free(group_material);
      free(group_options);
      group_material = copy_text(f[3]);
      group_options = copy_text(f[4]);
    }
    r.id = copy_text(f[0]);
    rows[row_count++] = r;
  }
  if (!flush_group(out, argv[1], &written)) return 2;
  free(group_material);
  free(group_options);
  fclose(in);
  if (fclose(out) != 0) { fprintf(stderr, "%s: cannot be written\n", argv[2]); return 2; }
  printf("%ld results -> %s\n", written, argv[2]);
  return 0;
}
