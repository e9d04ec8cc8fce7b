/* A grouper written in plain C against svgmotion/plugin.h only: it puts every element of the
 * document into one <g id="everything"> (by text: after the root's start tag, before its end
 * tag). Used by the test suite to check that out-of-tree plugins load and run. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <svgmotion/plugin.h>

#ifndef CLAIMED_ABI
#define CLAIMED_ABI SVGM_PLUGIN_ABI
#endif
#ifndef PLUGIN_NAME
#define PLUGIN_NAME "single"
#endif

static char* dup_str(const char* s) {
  char* p = malloc(strlen(s) + 1);
  if (p) strcpy(p, s);
  return p;
}

/* The value of "key": "..." in a flat JSON text (enough for run_dir; no escapes in our tests). */
static int json_string(const char* json, const char* key, char* out, size_t n) {
  char pat[64];
  snprintf(pat, sizeof pat, "\"%s\":\"", key);
  const char* p = strstr(json, pat);
  if (!p) return 0;
  p += strlen(pat);
  const char* e = strchr(p, '"');
  if (!e || (size_t)(e - p) >= n) return 0;
  memcpy(out, p, (size_t)(e - p));
  out[e - p] = 0;
  return 1;
}

static int run(const svgm_host* host, const char* request, char** response) {
  (void)host;
  char dir[4096], path[4200];
  if (!json_string(request, "run_dir", dir, sizeof dir)) {
    *response = dup_str("{\"ok\": false, \"error\": \"no run_dir in the request\"}");
    return 1;
  }
  snprintf(path, sizeof path, "%s/input.svg", dir);
  FILE* f = fopen(path, "rb");
  if (!f) {
    *response = dup_str("{\"ok\": false, \"error\": \"cannot open input.svg\"}");
    return 1;
  }
  fseek(f, 0, SEEK_END);
  long size = ftell(f);
  fseek(f, 0, SEEK_SET);
  char* text = malloc((size_t)size + 1);
  size_t got = fread(text, 1, (size_t)size, f);
  text[got] = 0;
  fclose(f);
  char* open = strstr(text, "<svg");
  char* open_end = open ? strchr(open, '>') : NULL;
  char* close = NULL;
  for (char* p = strstr(text, "</svg>"); p; p = strstr(p + 1, "</svg>")) close = p;
  if (!open_end || !close) {
    free(text);
    *response = dup_str("{\"ok\": false, \"error\": \"input.svg has no <svg> element\"}");
    return 1;
  }
  snprintf(path, sizeof path, "%s/grouped.svg", dir);
  FILE* o = fopen(path, "wb");
  fwrite(text, 1, (size_t)(open_end + 1 - text), o);
  fputs("<g id=\"everything\">", o);
  fwrite(open_end + 1, 1, (size_t)(close - open_end - 1), o);
  fputs("</g>", o);
  fputs(close, o);
  fclose(o);
  free(text);
  *response = dup_str("{\"ok\": true, \"message\": \"one group\"}");
  return 0;
}

static void free_string(char* s) { free(s); }

SVGM_PLUGIN_EXPORT const svgm_plugin* svgm_plugin_entry(void) {
  static const svgm_plugin d = {CLAIMED_ABI, sizeof(svgm_plugin), "grouper", PLUGIN_NAME, "1",
                                "everything in one group", run, free_string};
  return &d;
}
