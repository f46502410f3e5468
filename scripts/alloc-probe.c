/*
 * alloc-probe: a JVMTI agent that names the code behind a one-off allocation the zero-allocation
 * guard (`bench --fail-on-alloc`) reports on a framework thread but cannot place.
 *
 * It asks the JVM to sample every allocation (heap sampling interval 0) and, once armed, prints
 * to stderr each allocation made on one of rtaware's release-path threads (the task threads, pool
 * workers, watchdog and the pool's statistics recorder: named "rtaware-" but not one of the
 * observers ThreadNames lists as off that path), with its class, size, seconds since the JVM
 * started, and the Java stack. Arm it after the warm-up, e.g. 16 s into the guard's 30 s run.
 * Sampling every allocation slows code that allocates, not code that does not: the threads it
 * watches allocate nothing in steady state.
 *
 * Build and use (JDK 11 or later):
 *   gcc -shared -fPIC -O2 -I"$JAVA_HOME/include" -I"$JAVA_HOME/include/linux" \
 *       -o alloc-probe.so scripts/alloc-probe.c
 *   RTAWARE_JAVA_OPTS="-XX:+UnlockExperimentalVMOptions -XX:+UseEpsilonGC -Xms64m -Xmx64m \
 *       -agentpath:$PWD/alloc-probe.so=16" \
 *       ./rtaware bench --executor pooled --chain --tasks 8 --period 1ms --work 0 --duration 30s \
 *       --fail-on-alloc --quiet
 * The option is the delay before arming, in seconds (default 16).
 */
#include <jvmti.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MAX_FRAMES 24

static volatile int armed;
static int arm_after_s = 16;
static double started_s;
static pthread_mutex_t print_lock = PTHREAD_MUTEX_INITIALIZER;

/* The observers off the release path (io.rtaware.core.agent.ThreadNames). */
static const char *const OFF_PATH[] = {"rtaware-console", "rtaware-shutdown", "rtaware-stop",
                                       "rtaware-recorder", "rtaware-live-publisher", NULL};

static double monotonic_s(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec / 1e9;
}

static int on_release_path(const char *name) {
    if (strncmp(name, "rtaware-", 8) != 0 || strncmp(name, "rtaware-live-http-", 18) == 0) {
        return 0;
    }
    for (int i = 0; OFF_PATH[i] != NULL; i++) {
        if (strcmp(name, OFF_PATH[i]) == 0) {
            return 0;
        }
    }
    return 1;
}

static void *arm_later(void *unused) {
    (void) unused;
    sleep(arm_after_s);
    armed = 1;
    fprintf(stderr, "alloc-probe: armed at %.3f s\n", monotonic_s() - started_s);
    return NULL;
}

static void print_frame(jvmtiEnv *jvmti, const jvmtiFrameInfo *frame) {
    char *method = NULL, *signature = NULL, *klass = NULL;
    jclass declaring;
    (*jvmti)->GetMethodName(jvmti, frame->method, &method, &signature, NULL);
    if ((*jvmti)->GetMethodDeclaringClass(jvmti, frame->method, &declaring) == JVMTI_ERROR_NONE) {
        (*jvmti)->GetClassSignature(jvmti, declaring, &klass, NULL);
    }
    fprintf(stderr, "alloc-probe:     at %s.%s%s bci %ld\n", klass ? klass : "?", method ? method : "?",
            signature ? signature : "", (long) frame->location);
    (*jvmti)->Deallocate(jvmti, (unsigned char *) method);
    (*jvmti)->Deallocate(jvmti, (unsigned char *) signature);
    (*jvmti)->Deallocate(jvmti, (unsigned char *) klass);
}

static void JNICALL on_allocation(jvmtiEnv *jvmti, JNIEnv *jni, jthread thread, jobject object,
                                  jclass object_class, jlong size) {
    (void) jni;
    (void) object;
    jvmtiThreadInfo info;
    if (!armed || (*jvmti)->GetThreadInfo(jvmti, thread, &info) != JVMTI_ERROR_NONE || info.name == NULL) {
        return;
    }
    if (on_release_path(info.name)) {
        char *class_name = NULL;
        jvmtiFrameInfo frames[MAX_FRAMES];
        jint count = 0;
        (*jvmti)->GetClassSignature(jvmti, object_class, &class_name, NULL);
        (*jvmti)->GetStackTrace(jvmti, thread, 0, MAX_FRAMES, frames, &count);
        pthread_mutex_lock(&print_lock);
        fprintf(stderr, "alloc-probe: %.3f s, thread %s, %s, %ld bytes\n", monotonic_s() - started_s, info.name,
                class_name ? class_name : "?", (long) size);
        for (int i = 0; i < count; i++) {
            print_frame(jvmti, &frames[i]);
        }
        fflush(stderr);
        pthread_mutex_unlock(&print_lock);
        (*jvmti)->Deallocate(jvmti, (unsigned char *) class_name);
    }
    (*jvmti)->Deallocate(jvmti, (unsigned char *) info.name);
}

JNIEXPORT jint JNICALL Agent_OnLoad(JavaVM *vm, char *options, void *reserved) {
    (void) reserved;
    jvmtiEnv *jvmti;
    started_s = monotonic_s();
    if (options != NULL && *options != '\0') {
        arm_after_s = atoi(options);
    }
    if ((*vm)->GetEnv(vm, (void **) &jvmti, JVMTI_VERSION_11) != JNI_OK) {
        fprintf(stderr, "alloc-probe: this JVM has no JVMTI 11 (JDK 11 or later is needed)\n");
        return JNI_ERR;
    }
    jvmtiCapabilities capabilities;
    memset(&capabilities, 0, sizeof capabilities);
    capabilities.can_generate_sampled_object_alloc_events = 1;
    jvmtiEventCallbacks callbacks;
    memset(&callbacks, 0, sizeof callbacks);
    callbacks.SampledObjectAlloc = on_allocation;
    if ((*jvmti)->AddCapabilities(jvmti, &capabilities) != JVMTI_ERROR_NONE
        || (*jvmti)->SetEventCallbacks(jvmti, &callbacks, sizeof callbacks) != JVMTI_ERROR_NONE
        || (*jvmti)->SetEventNotificationMode(jvmti, JVMTI_ENABLE, JVMTI_EVENT_SAMPLED_OBJECT_ALLOC, NULL)
               != JVMTI_ERROR_NONE
        || (*jvmti)->SetHeapSamplingInterval(jvmti, 0) != JVMTI_ERROR_NONE) {
        fprintf(stderr, "alloc-probe: this JVM cannot sample every allocation\n");
        return JNI_ERR;
    }
    pthread_t armer;
    pthread_create(&armer, NULL, arm_later, NULL);
    pthread_detach(armer);
    return JNI_OK;
}
