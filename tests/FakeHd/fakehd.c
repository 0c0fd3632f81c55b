/*
 * Fake libHD: the subset of the OpenHaptics HD API that RobotControl's Touch back end uses, for tests.
 *
 * - Devices: two by default after fakehd_reset(), "right" and "left" (HD_DEFAULT_DEVICE is the first).
 * - The scheduler runs every scheduled callback from its own thread at the set rate (1 kHz by default).
 * - Each device plays a script of keyframes (transform, joint and gimbal angles, buttons), indexed by the device's
 *   frame count (hdBeginFrame increments it) and held until the next keyframe.
 * - Every hdSetDoublev(HD_CURRENT_FORCE) is recorded with its frame and whether force output was enabled.
 * - Failures on cue: init failure, calibration state, an error at a frame, a device unplugged from a frame on.
 *
 * The enum values are those of OpenHaptics' hdDefines.h (checked against a second copy: see docs/touch.md).
 */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdatomic.h>
#include <stddef.h>
#include <string.h>
#include <time.h>

#define EXPORT __attribute__((visibility("default")))

typedef unsigned int HHD;
typedef unsigned int HDenum;
typedef unsigned int HDerror;
typedef unsigned int HDCallbackCode;
typedef unsigned long HDSchedulerHandle;
typedef HDCallbackCode (*HDSchedulerCallback)(void *user_data);
typedef struct { HDerror errorCode; int internalErrorCode; HHD hHD; } HDErrorInfo;

enum {
    HD_SUCCESS_ = 0x0000, HD_EXCEEDED_MAX_FORCE_ = 0x0201, HD_DEVICE_FAULT_ = 0x0300, HD_COMM_ERROR_ = 0x0302,
    HD_COMM_CONFIG_ERROR_ = 0x0303, HD_ILLEGAL_BEGIN_ = 0x0400, HD_ILLEGAL_END_ = 0x0401, HD_INVALID_ENUM_ = 0x0100,
    HD_CURRENT_BUTTONS_ = 0x2000, HD_CURRENT_TRANSFORM_ = 0x2052, HD_CURRENT_JOINT_ANGLES_ = 0x2100,
    HD_CURRENT_GIMBAL_ANGLES_ = 0x2150, HD_DEVICE_MODEL_TYPE_ = 0x2501, HD_DEVICE_SERIAL_NUMBER_ = 0x2504,
    HD_NOMINAL_MAX_FORCE_ = 0x2603, HD_NOMINAL_MAX_CONTINUOUS_FORCE_ = 0x2604, HD_CURRENT_FORCE_ = 0x2700,
    HD_FORCE_OUTPUT_ = 0x4000, HD_CALIBRATION_OK_ = 0x5000,
};
#define HD_INVALID_HANDLE_ 0xFFFFFFFFu

#define MAX_DEVICES 4
#define MAX_KEYS 64
#define MAX_FORCES 65536
#define MAX_CALLBACKS 8

typedef struct { long frame; double transform[16]; double joints[3]; double gimbal[3]; int buttons; } Key;
typedef struct { long frame; double force[3]; int enabled; } ForceRecord;

typedef struct {
    char name[64];
    char serial[32];
    int present;
    int initialised;
    int fail_init;
    unsigned calibration;
    double max_force;
    double max_continuous;
    int force_output;
    int ever_enabled;
    int in_frame;
    long frames;
    Key keys[MAX_KEYS];
    int key_count;
    long fail_frame;        /* -1: never */
    unsigned fail_code;
    int fail_internal;
    int fail_persistent;    /* unplugged: the error repeats and the readings freeze */
    ForceRecord forces[MAX_FORCES];
    atomic_long force_count;
} Device;

static Device devices[MAX_DEVICES];
static pthread_mutex_t gate = PTHREAD_MUTEX_INITIALIZER;
static _Thread_local int current = -1;
static HDErrorInfo last_error;
static int has_error;

static HDSchedulerCallback callbacks[MAX_CALLBACKS];
static void *callback_data[MAX_CALLBACKS];
static unsigned long rate_hz = 1000;
static pthread_t thread;
static atomic_int running;
static atomic_long scheduler_ticks;
static atomic_int init_calls;

static void set_error(HDerror code, int internal, HHD handle)
{
    last_error.errorCode = code;
    last_error.internalErrorCode = internal;
    last_error.hHD = handle;
    has_error = 1;
}

static Device *cur(void) { return current >= 0 && current < MAX_DEVICES ? &devices[current] : NULL; }

static void add_device(int i, const char *name, const char *serial)
{
    Device *d = &devices[i];
    memset(d, 0, sizeof *d);
    strncpy(d->name, name, sizeof d->name - 1);
    strncpy(d->serial, serial, sizeof d->serial - 1);
    d->present = 1;
    d->calibration = HD_CALIBRATION_OK_;
    d->max_force = 3.3;
    d->max_continuous = 0.88;
    d->fail_frame = -1;
    d->key_count = 1;
    d->keys[0].transform[0] = d->keys[0].transform[5] = d->keys[0].transform[10] = d->keys[0].transform[15] = 1.0;
}

static const Key *key_at(const Device *d, long frame)
{
    const Key *k = &d->keys[0];
    for (int i = 1; i < d->key_count && d->keys[i].frame <= frame; i++) k = &d->keys[i];
    return k;
}

static long reading_frame(const Device *d)
{
    return d->fail_persistent && d->fail_frame >= 0 && d->frames > d->fail_frame ? d->fail_frame : d->frames;
}

/* ---- HD API ------------------------------------------------------------------------------------------------ */

EXPORT HHD hdInitDevice(const char *name)
{
    atomic_fetch_add(&init_calls, 1);
    pthread_mutex_lock(&gate);
    int found = -1;
    for (int i = 0; i < MAX_DEVICES && found < 0; i++)
        if (devices[i].present && (name == NULL || strcmp(name, devices[i].name) == 0)) found = i;
    if (found < 0 || devices[found].fail_init) {
        set_error(found < 0 ? HD_COMM_CONFIG_ERROR_ : HD_DEVICE_FAULT_, found < 0 ? -1 : 42, HD_INVALID_HANDLE_);
        pthread_mutex_unlock(&gate);
        return HD_INVALID_HANDLE_;
    }
    devices[found].initialised = 1;
    current = found;
    pthread_mutex_unlock(&gate);
    return (HHD)found;
}

EXPORT void hdDisableDevice(HHD h)
{
    if (h < MAX_DEVICES) { devices[h].initialised = 0; devices[h].force_output = 0; }
}

EXPORT void hdMakeCurrentDevice(HHD h)
{
    if (h < MAX_DEVICES && devices[h].initialised) current = (int)h;
    else set_error(0x0104 /* HD_BAD_HANDLE */, 0, h);
}

EXPORT void hdBeginFrame(HHD h)
{
    if (h >= MAX_DEVICES || devices[h].in_frame) { set_error(HD_ILLEGAL_BEGIN_, 0, h); return; }
    current = (int)h;
    devices[h].in_frame = 1;
}

EXPORT void hdEndFrame(HHD h)
{
    if (h >= MAX_DEVICES || !devices[h].in_frame) { set_error(HD_ILLEGAL_END_, 0, h); return; }
    Device *d = &devices[h];
    d->in_frame = 0;
    if (d->fail_frame >= 0 && (d->frames == d->fail_frame || (d->fail_persistent && d->frames > d->fail_frame)))
        set_error(d->fail_code, d->fail_internal, h);
    d->frames++;
}

EXPORT void hdGetDoublev(HDenum what, double *out)
{
    Device *d = cur();
    if (!d) { set_error(0x0104, 0, HD_INVALID_HANDLE_); return; }
    const Key *k = key_at(d, reading_frame(d));
    switch (what) {
    case HD_CURRENT_TRANSFORM_: memcpy(out, k->transform, sizeof k->transform); break;
    case HD_CURRENT_JOINT_ANGLES_: memcpy(out, k->joints, sizeof k->joints); break;
    case HD_CURRENT_GIMBAL_ANGLES_: memcpy(out, k->gimbal, sizeof k->gimbal); break;
    case HD_NOMINAL_MAX_FORCE_: out[0] = d->max_force; break;
    case HD_NOMINAL_MAX_CONTINUOUS_FORCE_: out[0] = d->max_continuous; break;
    default: set_error(HD_INVALID_ENUM_, (int)what, (HHD)current);
    }
}

EXPORT void hdGetIntegerv(HDenum what, int *out)
{
    Device *d = cur();
    if (!d || what != HD_CURRENT_BUTTONS_) { set_error(HD_INVALID_ENUM_, (int)what, (HHD)current); return; }
    out[0] = key_at(d, reading_frame(d))->buttons;
}

EXPORT const char *hdGetString(HDenum what)
{
    Device *d = cur();
    if (!d) return "";
    if (what == HD_DEVICE_SERIAL_NUMBER_) return d->serial;
    if (what == HD_DEVICE_MODEL_TYPE_) return "Touch (fake)";
    set_error(HD_INVALID_ENUM_, (int)what, (HHD)current);
    return "";
}

EXPORT void hdSetDoublev(HDenum what, const double *value)
{
    Device *d = cur();
    if (!d || what != HD_CURRENT_FORCE_ || !d->in_frame) { set_error(HD_INVALID_ENUM_, (int)what, (HHD)current); return; }
    long n = atomic_load(&d->force_count);
    if (n < MAX_FORCES) {
        ForceRecord *r = &d->forces[n];
        r->frame = d->frames;
        memcpy(r->force, value, sizeof r->force);
        r->enabled = d->force_output;
        atomic_store(&d->force_count, n + 1);
    }
}

EXPORT void hdEnable(HDenum what)
{
    Device *d = cur();
    if (d && what == HD_FORCE_OUTPUT_) { d->force_output = 1; d->ever_enabled = 1; }
}

EXPORT void hdDisable(HDenum what)
{
    Device *d = cur();
    if (d && what == HD_FORCE_OUTPUT_) d->force_output = 0;
}

EXPORT HDenum hdCheckCalibration(void)
{
    Device *d = cur();
    return d ? d->calibration : 0;
}

EXPORT HDErrorInfo hdGetError(void)
{
    HDErrorInfo e = { HD_SUCCESS_, 0, HD_INVALID_HANDLE_ };
    if (has_error) { e = last_error; has_error = 0; }
    return e;
}

EXPORT const char *hdGetErrorString(HDerror code)
{
    switch (code) {
    case HD_SUCCESS_: return "no error";
    case HD_EXCEEDED_MAX_FORCE_: return "fake: exceeded the maximum force";
    case HD_DEVICE_FAULT_: return "fake: device fault";
    case HD_COMM_ERROR_: return "fake: communication error (device unplugged)";
    case HD_COMM_CONFIG_ERROR_: return "fake: no such device configured";
    default: return "fake: error";
    }
}

static void *scheduler_main(void *unused)
{
    (void)unused;
    struct timespec next;
    clock_gettime(CLOCK_MONOTONIC, &next);
    while (atomic_load(&running)) {
        for (int i = 0; i < MAX_CALLBACKS; i++)
            if (callbacks[i] && callbacks[i](callback_data[i]) != 1 /* HD_CALLBACK_CONTINUE */) callbacks[i] = NULL;
        atomic_fetch_add(&scheduler_ticks, 1);
        next.tv_nsec += (long)(1000000000UL / rate_hz);
        while (next.tv_nsec >= 1000000000L) { next.tv_nsec -= 1000000000L; next.tv_sec++; }
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL);
    }
    return NULL;
}

EXPORT void hdSetSchedulerRate(unsigned long rate) { if (rate > 0 && rate <= 10000) rate_hz = rate; }

EXPORT void hdStartScheduler(void)
{
    if (atomic_exchange(&running, 1)) return;
    pthread_create(&thread, NULL, scheduler_main, NULL);
}

EXPORT void hdStopScheduler(void)
{
    if (!atomic_exchange(&running, 0)) return;
    pthread_join(thread, NULL);
}

EXPORT HDSchedulerHandle hdScheduleAsynchronous(HDSchedulerCallback callback, void *data, unsigned short priority)
{
    (void)priority;
    for (int i = 0; i < MAX_CALLBACKS; i++)
        if (!callbacks[i]) { callback_data[i] = data; callbacks[i] = callback; return (HDSchedulerHandle)(i + 1); }
    set_error(0x0501 /* HD_SCHEDULER_FULL */, 0, HD_INVALID_HANDLE_);
    return 0;
}

EXPORT void hdUnschedule(HDSchedulerHandle handle)
{
    if (handle >= 1 && handle <= MAX_CALLBACKS) callbacks[handle - 1] = NULL;
}

/* ---- Test control ------------------------------------------------------------------------------------------ */

/* Stops the scheduler and restores the default devices ("right", "left"), calibrated, at rest at the origin. */
EXPORT void fakehd_reset(void)
{
    hdStopScheduler();
    memset(callbacks, 0, sizeof callbacks);
    rate_hz = 1000;
    has_error = 0;
    atomic_store(&scheduler_ticks, 0);
    atomic_store(&init_calls, 0);
    add_device(0, "right", "FAKE-0001");
    add_device(1, "left", "FAKE-0002");
    for (int i = 2; i < MAX_DEVICES; i++) memset(&devices[i], 0, sizeof devices[i]);
}

static Device *named(const char *name)
{
    for (int i = 0; i < MAX_DEVICES; i++)
        if (devices[i].present && strcmp(devices[i].name, name) == 0) return &devices[i];
    return NULL;
}

/* Adds a keyframe from the device's frame `frame` on (frame 0 replaces the rest pose). 0 on success. */
EXPORT int fakehd_script_key(const char *name, long frame, const double transform[16], const double joints[3],
                             const double gimbal[3], int buttons)
{
    Device *d = named(name);
    if (!d) return -1;
    Key *k = frame == 0 ? &d->keys[0] : d->key_count < MAX_KEYS ? &d->keys[d->key_count++] : NULL;
    if (!k) return -2;
    k->frame = frame;
    memcpy(k->transform, transform, sizeof k->transform);
    memcpy(k->joints, joints, sizeof k->joints);
    memcpy(k->gimbal, gimbal, sizeof k->gimbal);
    k->buttons = buttons;
    return 0;
}

EXPORT int fakehd_fail_init(const char *name, int fail) { Device *d = named(name); if (!d) return -1; d->fail_init = fail; return 0; }

EXPORT int fakehd_set_calibration(const char *name, unsigned state) { Device *d = named(name); if (!d) return -1; d->calibration = state; return 0; }

EXPORT int fakehd_set_limits(const char *name, double max_force, double max_continuous)
{
    Device *d = named(name);
    if (!d) return -1;
    d->max_force = max_force;
    d->max_continuous = max_continuous;
    return 0;
}

/* From frame `frame`, hdGetError reports `code` (once; every frame and with frozen readings when `persistent`). */
EXPORT int fakehd_fail_at(const char *name, long frame, unsigned code, int internal, int persistent)
{
    Device *d = named(name);
    if (!d) return -1;
    d->fail_code = code;
    d->fail_internal = internal;
    d->fail_persistent = persistent;
    d->fail_frame = frame;
    return 0;
}

EXPORT long fakehd_frames(const char *name) { Device *d = named(name); return d ? d->frames : -1; }

EXPORT int fakehd_force_output_ever_enabled(const char *name) { Device *d = named(name); return d ? d->ever_enabled : -1; }

EXPORT int fakehd_is_initialised(const char *name) { Device *d = named(name); return d ? d->initialised : -1; }

EXPORT int fakehd_scheduler_running(void) { return atomic_load(&running); }

/* Copies up to `max` recorded forces (frame, fx, fy, fz, enabled: five doubles each) from index `from`; returns how many. */
EXPORT long fakehd_forces(const char *name, long from, double *out, long max)
{
    Device *d = named(name);
    if (!d) return -1;
    long n = atomic_load(&d->force_count);
    long copied = 0;
    for (long i = from; i < n && copied < max; i++, copied++) {
        const ForceRecord *r = &d->forces[i];
        out[copied * 5] = (double)r->frame;
        memcpy(&out[copied * 5 + 1], r->force, sizeof r->force);
        out[copied * 5 + 4] = r->enabled;
    }
    return copied;
}

EXPORT long fakehd_force_count(const char *name) { Device *d = named(name); return d ? atomic_load(&d->force_count) : -1; }

__attribute__((constructor)) static void fakehd_init(void) { fakehd_reset(); }
