/* Conformance harness in C99 (docs/conformance.md): reads the vectors.csv that
 * `dspbr conformance generate` writes, calls the renderer's eval function for every vector and
 * writes the results file that `dspbr conformance check` judges:
 *
 *   conformance_harness VECTORS.csv RESULTS.csv
 *   dspbr conformance check VECTORS.json RESULTS.csv --out REPORT
 *
 * The renderer plugs in through one function (renderer.h): link your own renderer_eval instead of
 * reference_renderer.cpp (the reference BSDF, used here so that the example passes). A GLSL or
 * HLSL implementation runs through `dspbr conformance run --glsl/--hlsl` instead. A vector the
 * renderer does not support gets no line (NOT SUPPLIED), a pdf it does not compute an empty field.
 * Exit status 0, or 2 with one line on stderr naming the file and the line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "renderer.h"

enum { kMaxLine = 1 << 16, kMaxFields = 32 };

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
    double vl[6], f_cos[3], pdf = NAN;
    if (split_csv(line, f) < 11 || !parse_numbers(f + 5, vl, 6)) {
      fprintf(stderr, "%s: line %ld: malformed vector\n", argv[1], number);
      return 2;
    }
    const int status = renderer_eval(f[3], f[4], vl, vl + 3, f_cos, &pdf);
    if (status != RENDERER_OK && status != RENDERER_UNSUPPORTED) {
      fprintf(stderr, "%s: line %ld (id '%s'): the renderer cannot evaluate this material\n", argv[1], number, f[0]);
      return 2;
    }
    if (status == RENDERER_UNSUPPORTED) continue; /* no result: NOT SUPPLIED */
    write_csv_field(out, f[0]);
    fprintf(out, ",%.17g,%.17g,%.17g,", f_cos[0], f_cos[1], f_cos[2]);
    if (!isnan(pdf)) fprintf(out, "%.17g", pdf); /* an empty field: not supplied */
    fputc('\n', out);
    ++written;
  }
  fclose(in);
  if (fclose(out) != 0) { fprintf(stderr, "%s: cannot be written\n", argv[2]); return 2; }
  printf("%ld results -> %s\n", written, argv[2]);
  return 0;
}
