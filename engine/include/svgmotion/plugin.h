/* svgmotion/plugin.h: the stage plugin ABI (C, so a plugin may be built by another compiler or
 * written in another language).
 *
 * A plugin is a shared module exporting one function, svgm_plugin_entry(), that returns a
 * pointer to a static descriptor. The host checks `abi` against SVGM_PLUGIN_ABI and `size`
 * against the size it knows, refuses unknown stages and duplicate (stage, name) pairs, then
 * calls `run` with a JSON request and expects a JSON response.
 *
 * Request (UTF-8 JSON object): {"abi": 1, "stage": "...", "run_dir": "/abs/dir",
 *   "inputs": {"svg": "grouped.svg", ...}, "outputs": {"svg": "recolored.svg", ...},
 *   "config": {...this stage's config section...}, "prompt": "...", "seed": 0}
 * Paths in "inputs"/"outputs" are relative to run_dir. A stage reads its inputs and writes
 * exactly the promised outputs there; the host checks they exist afterwards.
 * File names are bytes: a string that is not valid UTF-8 (a Latin-1 run directory, say) is
 * sent with U+FFFD in place of each stray byte, and its bytes, in hex, under
 * "raw_strings": {"<JSON pointer, e.g. /run_dir>": "2f746d70..."}; put them back before
 * opening the path (svgmotion/utf8_text.h unpack_raw_strings does). The response must be UTF-8.
 * Response: {"ok": true, "message": "...", ...} or {"ok": false, "error": "one line"}.
 *
 * Contract:
 * - run() is called on the host's main thread, one call at a time; it may block for as long
 *   as the stage needs, and should call host->progress now and then and return early (with an
 *   error) when host->cancelled() becomes non-zero.
 * - *response_json is allocated by the plugin and released by the host with free_string();
 *   strings passed to the plugin stay valid only during the call.
 * - run() returns 0 on success and non-zero on failure (then the response's "error" is the
 *   message shown to the user). No exception or longjmp may cross this boundary.
 */
#ifndef SVGMOTION_PLUGIN_H
#define SVGMOTION_PLUGIN_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SVGM_PLUGIN_ABI 1

#if defined(_WIN32)
#define SVGM_PLUGIN_EXPORT __declspec(dllexport)
#else
#define SVGM_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

typedef struct svgm_host svgm_host;

/* What the host offers a running plugin. All callbacks are safe to call from run()'s thread. */
struct svgm_host {
  uint32_t abi;  /* SVGM_PLUGIN_ABI of the host */
  uint32_t size; /* sizeof(svgm_host) in the host */
  const char* host_version;
  void* context; /* the host's; do not touch */
  /* level: 0 debug, 1 info, 2 warning, 3 error; message is one line. */
  void (*log)(const svgm_host* host, int level, const char* message);
  /* fraction in [0, 1] of this stage, with a short note (may be NULL). The host draws its ETA
     as if the fraction were the share of the stage's time done so far (setup included); a note
     whose words change ("reading ...", then "judging ...") is shown at once. */
  void (*progress)(const svgm_host* host, double fraction, const char* note);
  /* non-zero once the user asked to stop. */
  int (*cancelled)(const svgm_host* host);
};

typedef struct svgm_plugin {
  uint32_t abi;        /* SVGM_PLUGIN_ABI the plugin was built against */
  uint32_t size;       /* sizeof(svgm_plugin) the plugin was built with */
  const char* stage;   /* "grouper", "recolorer", "video", "ranker", "layers", "tracker", "fitter" */
  const char* name;    /* "structural", "spherepack", ... */
  const char* version; /* the plugin's own version */
  const char* description;
  int (*run)(const svgm_host* host, const char* request_json, char** response_json);
  void (*free_string)(char* s);
} svgm_plugin;

/* The one exported symbol. */
typedef const svgm_plugin* (*svgm_plugin_entry_fn)(void);
SVGM_PLUGIN_EXPORT const svgm_plugin* svgm_plugin_entry(void);

#ifdef __cplusplus
}
#endif

#endif /* SVGMOTION_PLUGIN_H */
