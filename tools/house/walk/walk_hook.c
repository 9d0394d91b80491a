// The hook of tools/house/walk/walk.py (issue 58): linked into an iwb compiled with
// -finstrument-functions-after-inlining, it writes the main thread's first-visit walk through
// the workbench's own functions. IWB_WALK_MAP names the functions to follow (lines "ADDRESS ID",
// ADDRESS hexadecimal from the executable's load address, sorted); every other function (the
// libraries' templates, the standard library) is transparent. A call is followed the first time
// its edge (the calling workbench function, the called one) is taken and skipped with all it
// calls after that, so loops count once; the walk is written to IWB_WALK_OUT as lines "E ID"
// (entered) and "X ID" (left). Frames left by an exception are dropped on the next event, by
// their frame addresses (the build keeps frame pointers).
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/syscall.h>
#include <unistd.h>

#define NI __attribute__((no_instrument_function))
#define MAX_DEPTH 65536
#define EDGE_SLOTS (1u << 22)

struct frame {
  uintptr_t at;   // the instrumented function's frame address
  int32_t fn;     // its id, -1 where transparent
  int32_t src;    // the innermost workbench function at or above it
  int skip;       // inside a call already walked
};

static uint64_t* addresses;
static int32_t* ids;
static size_t count;
static uintptr_t base;
static FILE* out;
static int state;  // 0 not loaded, 1 ready, -1 off
static struct frame stack[MAX_DEPTH];
static int depth;
static uint64_t* edges;
static __thread int thread_kind;  // 0 unknown, 1 main, 2 other

NI static void load(void) {
  const char* map = getenv("IWB_WALK_MAP");
  const char* path = getenv("IWB_WALK_OUT");
  state = -1;
  if (!map || !path) return;
  FILE* m = fopen(map, "r");
  if (!m) return;
  size_t cap = 1 << 16;
  addresses = malloc(cap * sizeof *addresses);
  ids = malloc(cap * sizeof *ids);
  unsigned long long a;
  int id;
  while (fscanf(m, "%llx %d", &a, &id) == 2) {
    if (count == cap) {
      cap *= 2;
      addresses = realloc(addresses, cap * sizeof *addresses);
      ids = realloc(ids, cap * sizeof *ids);
    }
    addresses[count] = a;
    ids[count++] = id;
  }
  fclose(m);
  edges = calloc(EDGE_SLOTS, sizeof *edges);
  Dl_info info;
  dladdr((void*)&load, &info);
  base = (uintptr_t)info.dli_fbase;
  out = fopen(path, "w");
  if (out) state = 1;
}

NI static int32_t id_of(void* fn) {
  const uint64_t a = (uintptr_t)fn - base;
  size_t lo = 0, hi = count;
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (addresses[mid] < a)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < count && addresses[lo] == a ? ids[lo] : -1;
}

// 1 the first time the edge is seen
NI static int first_time(int32_t from, int32_t to) {
  const uint64_t key = ((uint64_t)(uint32_t)(from + 1) << 32 | (uint32_t)to) + 1;
  uint64_t h = key * 0x9E3779B97F4A7C15ull;
  for (uint32_t i = (uint32_t)(h >> 40) & (EDGE_SLOTS - 1);; i = (i + 1) & (EDGE_SLOTS - 1)) {
    if (edges[i] == key) return 0;
    if (edges[i] == 0) {
      edges[i] = key;
      return 1;
    }
  }
}

NI static int on_main_thread(void) {
  if (thread_kind == 0) thread_kind = syscall(SYS_gettid) == getpid() ? 1 : 2;
  return thread_kind == 1;
}

// drops the frames an exception left: those at or below the frame address `at`
NI static void unwind_to(uintptr_t at) {
  while (depth > 0 && stack[depth - 1].at <= at) {
    const struct frame* f = &stack[--depth];
    if (f->fn >= 0 && !f->skip) fprintf(out, "X %d\n", f->fn);
  }
}

NI void __cyg_profile_func_enter(void* fn, void* site) {
  (void)site;
  if (state == 0) load();
  if (state != 1 || !on_main_thread()) return;
  const uintptr_t at = (uintptr_t)__builtin_frame_address(1);
  unwind_to(at);
  if (depth == MAX_DEPTH) return;
  const struct frame* parent = depth ? &stack[depth - 1] : NULL;
  struct frame f = {at, id_of(fn), parent ? parent->src : -1, parent ? parent->skip : 0};
  if (f.fn >= 0) {
    if (!f.skip && !first_time(f.src, f.fn)) f.skip = 1;
    if (!f.skip) fprintf(out, "E %d\n", f.fn);
    f.src = f.fn;
  }
  stack[depth++] = f;
}

NI void __cyg_profile_func_exit(void* fn, void* site) {
  (void)fn;
  (void)site;
  if (state != 1 || !on_main_thread()) return;
  const uintptr_t at = (uintptr_t)__builtin_frame_address(1);
  // the frames below this one (left by an exception), then this one
  while (depth > 0 && stack[depth - 1].at < at) {
    const struct frame* f = &stack[--depth];
    if (f->fn >= 0 && !f->skip) fprintf(out, "X %d\n", f->fn);
  }
  if (depth > 0 && stack[depth - 1].at == at) {
    const struct frame* f = &stack[--depth];
    if (f->fn >= 0 && !f->skip) fprintf(out, "X %d\n", f->fn);
  }
}

NI __attribute__((destructor)) static void finish(void) {
  if (state == 1) {
    unwind_to(UINTPTR_MAX);
    fclose(out);
    state = -1;
  }
}
