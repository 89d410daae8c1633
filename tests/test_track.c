/* test_track.c — trackers (SPEC 8): a track file's samples, the poses
 * between them (linear, slerp) against closed forms, the velocity of that
 * motion, the head's view, track time as simulation time, a tracker that
 * stops sending, and every bad line an error naming the file and line. */
#include <stdlib.h>
#include <unistd.h>
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "track.h"
#include "scene.h"

#define PI 3.14159265358979323846

static char err[512];

/* a file of the given text in a scratch folder; its path in path */
static int write_file(char *path, size_t n, const char *name, const char *text)
{
    FILE *f;
    snprintf(path, n, "%s/vroc-track-%ld-%s", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp", (long)getpid(), name);
    f = fopen(path, "w");
    if (!f) return -1;
    fputs(text, f);
    return fclose(f);
}

/* positions interpolate linearly, orientations by slerp: a quarter turn
 * about z over 1 s is an eighth of a turn at 0.5 s and spins at pi/2 rad/s */
static int test_pose_between_samples_is_lerp_and_slerp(void)
{
    vrTrack tr = {0, 0, 0};
    vrTrackerSample at;
    double v[3], w[3];
    quat q;
    vrTrackerSample a = vrScene_Sample(1, vec3_make(0, 0, 1), quat_identity(), 1);
    vrTrackerSample b = vrScene_Sample(2, vec3_make(2, -4, 1), quat_from_axis_angle(vec3_make(0, 0, 1), PI / 2), 0);
    ENSURE(vrTrack_Push(&tr, &a) == 0 && vrTrack_Push(&tr, &b) == 0);
    ENSURE(vrTrack_At(&tr, 1.5, &at) == 0);
    ENSURE_NEAR(at.position[0], 1, 1e-15);
    ENSURE_NEAR(at.position[1], -2, 1e-15);
    q = quat_make(at.orientation[0], at.orientation[1], at.orientation[2], at.orientation[3]);
    ENSURE_NEAR(quat_angle_between(q, quat_from_axis_angle(vec3_make(0, 0, 1), PI / 4)), 0, 1e-12);
    ENSURE(at.buttons == 1);                 /* the buttons of the sample at or before */
    ENSURE(vrTrack_At(&tr, 2, &at) == 0 && at.buttons == 0);
    ENSURE(vrTrack_Velocity(&tr, 1.25, v, w) == 0);
    ENSURE_NEAR(v[0], 2, 1e-15);
    ENSURE_NEAR(v[1], -4, 1e-15);
    ENSURE_NEAR(w[2], PI / 2, 1e-12);
    ENSURE_NEAR(w[0], 0, 1e-15);
    vrTrack_Free(&tr);
    return 0;
}

/* the short way round: q and -q are one orientation */
static int test_slerp_takes_the_short_way(void)
{
    vrTrack tr = {0, 0, 0};
    vrTrackerSample at, a, b;
    double v[3], w[3];
    quat q = quat_from_axis_angle(vec3_make(1, 0, 0), 0.2);
    a = vrScene_Sample(0, vec3_zero(), quat_identity(), 0);
    b = vrScene_Sample(1, vec3_zero(), quat_make(-q.w, -q.x, -q.y, -q.z), 0);
    ENSURE(vrTrack_Push(&tr, &a) == 0 && vrTrack_Push(&tr, &b) == 0);
    ENSURE(vrTrack_Velocity(&tr, 0.5, v, w) == 0);
    ENSURE_NEAR(w[0], 0.2, 1e-12);
    ENSURE(vrTrack_At(&tr, 0.5, &at) == 0);
    q = quat_make(at.orientation[0], at.orientation[1], at.orientation[2], at.orientation[3]);
    ENSURE_NEAR(quat_angle_between(q, quat_from_axis_angle(vec3_make(1, 0, 0), 0.1)), 0, 1e-12);
    vrTrack_Free(&tr);
    return 0;
}

/* before the first sample the first holds, after the last the last: a
 * tracker that stops sending leaves the run going with its last pose */
static int test_tracker_that_stops_sending_holds_its_last_pose(void)
{
    vrWorld *w = vrScene_World(0.1, 0.01, 9.8);
    vrTrackerSample s = vrScene_Sample(0.2, vec3_make(1, 2, 3), quat_identity(), 1), at;
    ENSURE(vrScene_Sphere(w, "ball", 0.1, vec3_make(0, 0, 5), vec3_zero(), 1, 1) != VR_NO_OBJECT);
    ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HAND, &at) == -1);
    ENSURE(vrWorld_PushSample(w, VR_DEVICE_HAND, &s, err, sizeof err) == 0);
    ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HAND, &at) == 0 && at.position[1] == 2);
    ENSURE(vrScene_Step(w, 10) == 0);
    ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HAND, &at) == 0);
    ENSURE(at.position[0] == 1 && at.position[1] == 2 && at.position[2] == 3 && at.buttons == 1);
    ENSURE_NEAR(vrScene_State(w, vrWorld_FindObject(w, "ball")).position[2], 5 - 0.5 * 9.8, 1e-9);
    s.t = 0.5;   /* earlier than the world's time is fine, earlier than the last sample is not */
    ENSURE(vrWorld_PushSample(w, VR_DEVICE_HAND, &s, err, sizeof err) == 0);
    s.t = 0.4;
    ENSURE(vrWorld_PushSample(w, VR_DEVICE_HAND, &s, err, sizeof err) == -1);
    ENSURE_MSG(strstr(err, "before the hand's last") != NULL, "%s", err);
    vrWorld_Destroy(w);
    return 0;
}

/* track time is simulation time since `track`: a file read at t = 1 s
 * puts its sample at 0.5 s at 1.5 s; a later file replaces a device's
 * samples and leaves the other's */
static int test_track_time_counts_from_the_track_command(void)
{
    char path[512], path2[512];
    vrWorld *w = vrScene_World(0.25, 0.01, 0);
    vrTrackerSample at;
    ENSURE(write_file(path, sizeof path, "a.trk", "0 head 0 0 0 1 0 0 0\n0.5 head 1 0 0 1 0 0 0  # moved\n"
                                                  "0.5 hand 0 0 2 1 0 0 0 1\r\n") == 0);
    ENSURE(write_file(path2, sizeof path2, "b.trk", "\n# only the hand\n0 hand 7 0 0 1 0 0 0\n") == 0);
    ENSURE(vrScene_Sphere(w, "ball", 0.1, vec3_zero(), vec3_zero(), 1, 1) != VR_NO_OBJECT);
    ENSURE(vrScene_Step(w, 4) == 0);
    ENSURE_MSG(vrWorld_ReadTrack(w, path, err, sizeof err) == 0, "%s", err);
    ENSURE(vrScene_Step(w, 1) == 0);            /* t = 1.25: halfway */
    ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HEAD, &at) == 0);
    ENSURE_NEAR(at.position[0], 0.5, 1e-15);
    ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HAND, &at) == 0 && at.buttons == 1 && at.position[2] == 2);
    ENSURE_MSG(vrWorld_ReadTrack(w, path2, err, sizeof err) == 0, "%s", err);
    ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HAND, &at) == 0 && at.position[0] == 7 && at.buttons == 0);
    ENSURE(vrScene_Step(w, 1) == 0);
    ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HEAD, &at) == 0 && at.position[0] == 1);
    vrWorld_Restart(w);                         /* time starts again: so do the trackers */
    ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HEAD, &at) == -1);
    unlink(path), unlink(path2);
    vrWorld_Destroy(w);
    return 0;
}

typedef struct BadLine {
    const char *text;
    const char *message;   /* what the error says after FILE:LINE: */
} BadLine;

static const BadLine bad_lines[] = {
    {"0 head 0 0 0 1 0 0\n", "missing qz"},
    {"0 foot 0 0 0 1 0 0 0\n", "unknown device 'foot'"},
    {"x head 0 0 0 1 0 0 0\n", "t must be a finite decimal number"},
    {"0 head 0 0 nan 1 0 0 0\n", "z must be a finite decimal number"},
    {"0 head 0 0 0x1 1 0 0 0\n", "z must be a finite decimal number"},
    {"0 head 0 0 1e999 1 0 0 0\n", "z must be a finite decimal number"},
    {"0 head 0 0 0 2 0 0 0\n", "the quaternion must be a unit one"},
    {"0 head 0 0 0 1 0 0 0 1\n", "a head sample has no buttons"},
    {"0 hand 0 0 0 1 0 0 0 4\n", "buttons must be an integer 0..3"},
    {"0 hand 0 0 0 1 0 0 0 1.5\n", "buttons must be an integer 0..3"},
    {"0 hand 0 0 0 1 0 0 0 1 9\n", "unexpected '9'"},
    {"-1 hand 0 0 0 1 0 0 0\n", "t must be >= 0"},
    {"2 hand 0 0 0 1 0 0 0\n1 head 0 0 0 1 0 0 0\n", "times never decrease"},
    {"0 hand 0 0 0 1 0 0 0\x01\n", "control byte 0x01"},
};

/* a bad line is an error naming the file and its line, and changes nothing */
static int test_bad_track_lines_name_file_and_line(void)
{
    vrWorld *w = vrScene_World(0.1, 0.01, 0);
    size_t k;
    for (k = 0; k < sizeof bad_lines / sizeof bad_lines[0]; k++) {
        char path[512], text[256], want[600];
        vrTrackerSample at;
        long line = 2 + (strchr(bad_lines[k].text, '\n')[1] != '\0');
        snprintf(text, sizeof text, "0 hand 1 1 1 1 0 0 0\n%s", bad_lines[k].text);
        ENSURE(write_file(path, sizeof path, "bad.trk", text) == 0);
        ENSURE(vrWorld_ReadTrack(w, path, err, sizeof err) == -1);
        snprintf(want, sizeof want, "%s:%ld: %s", path, line, bad_lines[k].message);
        ENSURE_MSG(strncmp(err, want, strlen(want)) == 0, "case %d: got \"%s\", want \"%s...\"", (int)k, err, want);
        ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HAND, &at) == -1);   /* nothing of the file taken */
        unlink(path);
    }
    ENSURE(vrWorld_ReadTrack(w, "/nonexistent/x.trk", err, sizeof err) == -1 && strstr(err, "/nonexistent/x.trk"));
    vrWorld_Destroy(w);
    return 0;
}

/* the head's frame: eyes at its origin, looking along its +y, up its +z;
 * turned a quarter about z it looks along -x, converging at the view's
 * focal distance */
static int test_head_pose_drives_the_view(void)
{
    vrView v = vrView_Default();
    vrTrackerSample head = vrScene_Sample(0, vec3_make(1, 2, 1.7), quat_from_axis_angle(vec3_make(0, 0, 1), PI / 2), 0);
    double dist = sqrt(8.0 * 8.0 + 2.0 * 2.0);   /* |look - eye| of the default view */
    vrView_FromHead(&v, &head);
    ENSURE(v.eye[0] == 1 && v.eye[1] == 2 && v.eye[2] == 1.7);
    ENSURE_NEAR(v.look[0], 1 - dist, 1e-12);
    ENSURE_NEAR(v.look[1], 2, 1e-12);
    ENSURE_NEAR(v.look[2], 1.7, 1e-12);
    ENSURE_NEAR(v.up[2], 1, 1e-15);
    ENSURE_NEAR(v.focal, dist, 1e-12);
    head = vrScene_Sample(0, vec3_zero(), quat_from_axis_angle(vec3_make(1, 0, 0), PI / 2), 0);   /* looking up */
    v = vrView_Default();
    v.focal = 3;
    vrView_FromHead(&v, &head);
    ENSURE_NEAR(v.look[2], 3, 1e-12);
    ENSURE_NEAR(v.up[1], -1, 1e-12);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_pose_between_samples_is_lerp_and_slerp),
    TEST(test_slerp_takes_the_short_way),
    TEST(test_tracker_that_stops_sending_holds_its_last_pose),
    TEST(test_track_time_counts_from_the_track_command),
    TEST(test_bad_track_lines_name_file_and_line),
    TEST(test_head_pose_drives_the_view),
};

const vrTestSuite vrSuite_Track = {"track", tests, TEST_COUNT(tests), NULL, NULL, 0};
