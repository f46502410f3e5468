//! The JNI layer between rtaware's Java classes (`io.rtaware.zenoh.NativeZenoh`) and the official
//! Zenoh implementation. It only forwards: every decision (configuration, key expressions, what to
//! do with a sample) is taken on the Java side.
//!
//! Handles given to Java are raw pointers of boxed Rust objects, turned back into boxes exactly
//! once by the matching `close*`/`undeclare*` function. Samples of subscribers reach Java through
//! a mailbox: the subscriber callbacks (Zenoh's threads) append owned copies to a bounded queue,
//! and a Java thread takes them one at a time, copying payload and attachment into direct buffers
//! that Java allocated once, so the Java side allocates nothing per sample.

use std::collections::VecDeque;
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

use jni::objects::{JByteBuffer, JClass, JObject, JObjectArray, JString};
use jni::sys::{jboolean, jint, jlong, jobjectArray, jstring, JNI_TRUE};
use jni::JNIEnv;
use zenoh::key_expr::KeyExpr;
use zenoh::liveliness::LivelinessToken;
use zenoh::pubsub::{Publisher, Subscriber};
use zenoh::{Config, Session, Wait};

const ZENOH_EXCEPTION: &str = "io/rtaware/zenoh/ZenohException";

/// Runs `body`, turning an error or a panic into a `ZenohException` and `fallback`.
fn guarded<T>(env: &mut JNIEnv, fallback: T, body: impl FnOnce(&mut JNIEnv) -> Result<T, String>) -> T {
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| body(env)));
    match outcome {
        Ok(Ok(value)) => value,
        Ok(Err(message)) => {
            let _ = env.throw_new(ZENOH_EXCEPTION, message);
            fallback
        }
        Err(_) => {
            let _ = env.throw_new(ZENOH_EXCEPTION, "panic in the native Zenoh layer");
            fallback
        }
    }
}

fn java_string(env: &mut JNIEnv, s: &JString) -> Result<String, String> {
    env.get_string(s).map(Into::into).map_err(|e| format!("bad string argument: {e}"))
}

fn java_strings(env: &mut JNIEnv, array: &JObjectArray) -> Result<Vec<String>, String> {
    let n = env.get_array_length(array).map_err(|e| e.to_string())?;
    let mut out = Vec::with_capacity(n as usize);
    for i in 0..n {
        let element = env.get_object_array_element(array, i).map_err(|e| e.to_string())?;
        out.push(java_string(env, &JString::from(element))?);
    }
    Ok(out)
}

fn json_strings(values: &[String]) -> String {
    let quoted: Vec<String> = values.iter().map(|v| format!("{:?}", v)).collect();
    format!("[{}]", quoted.join(","))
}

/// A direct buffer's memory as a slice of `capacity` bytes.
fn direct<'a>(env: &mut JNIEnv, buffer: &JByteBuffer) -> Result<&'a mut [u8], String> {
    let address = env.get_direct_buffer_address(buffer).map_err(|e| format!("not a direct buffer: {e}"))?;
    let capacity = env.get_direct_buffer_capacity(buffer).map_err(|e| format!("not a direct buffer: {e}"))?;
    // SAFETY: the JVM guarantees `capacity` bytes at `address` while the buffer is reachable,
    // and the Java caller keeps it reachable for the duration of the call.
    Ok(unsafe { std::slice::from_raw_parts_mut(address, capacity) })
}

fn key_expr(text: String) -> Result<KeyExpr<'static>, String> {
    KeyExpr::try_from(text.clone()).map_err(|e| format!("invalid key expression '{text}': {e}"))
}

unsafe fn borrow<'a, T>(handle: jlong) -> Result<&'a T, String> {
    if handle == 0 {
        return Err("handle is closed".to_string());
    }
    Ok(&*(handle as *const T))
}

fn into_handle<T>(value: T) -> jlong {
    Box::into_raw(Box::new(value)) as jlong
}

// ---------------------------------------------------------------------------------------------
// Session

/// Opens a session. `mode` is "peer" or "client"; endpoints are Zenoh locators
/// (`tcp/127.0.0.1:7447`); `connect_timeout_ms` bounds the wait for the connect endpoints, and
/// with at least one connect endpoint the open fails when none can be reached in that time.
#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_open(
    mut env: JNIEnv,
    _class: JClass,
    mode: JString,
    connect: JObjectArray,
    listen: JObjectArray,
    multicast_scouting: jboolean,
    connect_timeout_ms: jlong,
) -> jlong {
    guarded(&mut env, 0, |env| {
        let mode = java_string(env, &mode)?;
        let connect = java_strings(env, &connect)?;
        let listen = java_strings(env, &listen)?;
        let mut config = Config::default();
        let mut set = |key: &str, value: String| {
            config.insert_json5(key, &value).map_err(|e| format!("configuration {key}={value}: {e}"))
        };
        set("mode", format!("{:?}", mode))?;
        set("connect/endpoints", json_strings(&connect))?;
        set("listen/endpoints", json_strings(&listen))?;
        set("scouting/multicast/enabled", (multicast_scouting == JNI_TRUE).to_string())?;
        if !connect.is_empty() {
            set("connect/timeout_ms", connect_timeout_ms.to_string())?;
            set("connect/exit_on_failure", "true".to_string())?;
        }
        let session = zenoh::open(config).wait().map_err(|e| format!("cannot open the Zenoh session: {e}"))?;
        Ok(into_handle(session))
    })
}

/// The session's Zenoh id as Zenoh prints it (lowercase hexadecimal).
#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_zid(mut env: JNIEnv, _class: JClass, session: jlong) -> jstring {
    guarded(&mut env, std::ptr::null_mut(), |env| {
        let session = unsafe { borrow::<Session>(session)? };
        let zid = session.zid().to_string();
        env.new_string(zid).map(JString::into_raw).map_err(|e| e.to_string())
    })
}

#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_close(mut env: JNIEnv, _class: JClass, session: jlong) {
    guarded(&mut env, (), |_| {
        if session != 0 {
            let session = unsafe { Box::from_raw(session as *mut Session) };
            session.close().wait().map_err(|e| format!("closing the Zenoh session: {e}"))?;
        }
        Ok(())
    })
}

// ---------------------------------------------------------------------------------------------
// Publisher

#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_declarePublisher(
    mut env: JNIEnv,
    _class: JClass,
    session: jlong,
    key: JString,
) -> jlong {
    guarded(&mut env, 0, |env| {
        let session = unsafe { borrow::<Session>(session)? };
        let key = key_expr(java_string(env, &key)?)?;
        let publisher = session.declare_publisher(key).wait().map_err(|e| format!("declaring a publisher: {e}"))?;
        Ok(into_handle(publisher))
    })
}

/// Publishes the first `length` bytes of `payload` with the first `attachment_length` bytes of
/// `attachment` (no attachment when `attachment_length` is negative).
#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_put(
    mut env: JNIEnv,
    _class: JClass,
    publisher: jlong,
    payload: JByteBuffer,
    length: jint,
    attachment: JByteBuffer,
    attachment_length: jint,
) {
    guarded(&mut env, (), |env| {
        let publisher = unsafe { borrow::<Publisher<'static>>(publisher)? };
        let bytes = direct(env, &payload)?;
        if length < 0 || length as usize > bytes.len() {
            return Err(format!("payload length {length} outside 0..{}", bytes.len()));
        }
        let mut put = publisher.put(bytes[..length as usize].to_vec());
        if attachment_length >= 0 {
            let extra = direct(env, &attachment)?;
            if attachment_length as usize > extra.len() {
                return Err(format!("attachment length {attachment_length} outside 0..{}", extra.len()));
            }
            put = put.attachment(extra[..attachment_length as usize].to_vec());
        }
        put.wait().map_err(|e| format!("publishing: {e}"))
    })
}

#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_undeclarePublisher(mut env: JNIEnv, _class: JClass, publisher: jlong) {
    guarded(&mut env, (), |_| {
        if publisher != 0 {
            let publisher = unsafe { Box::from_raw(publisher as *mut Publisher<'static>) };
            publisher.undeclare().wait().map_err(|e| format!("undeclaring a publisher: {e}"))?;
        }
        Ok(())
    })
}

// ---------------------------------------------------------------------------------------------
// Mailbox and subscribers

struct Sample {
    channel: jint,
    payload: Vec<u8>,
    attachment: Option<Vec<u8>>,
}

struct Queue {
    samples: VecDeque<Sample>,
    closed: bool,
    overflowed: u64,
}

/// A bounded queue filled by subscriber callbacks and emptied by one Java thread. When it is
/// full the oldest sample is dropped (and counted): for sensor data the newest value matters.
struct Mailbox {
    capacity: usize,
    queue: Mutex<Queue>,
    ready: Condvar,
}

impl Mailbox {
    fn offer(&self, sample: Sample) {
        let mut queue = self.queue.lock().unwrap_or_else(|p| p.into_inner());
        if queue.closed {
            return;
        }
        if queue.samples.len() >= self.capacity {
            queue.samples.pop_front();
            queue.overflowed += 1;
        }
        queue.samples.push_back(sample);
        self.ready.notify_one();
    }
}

#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_newMailbox(mut env: JNIEnv, _class: JClass, capacity: jint) -> jlong {
    guarded(&mut env, 0, |_| {
        if capacity <= 0 {
            return Err(format!("mailbox capacity {capacity} must be positive"));
        }
        let mailbox = Arc::new(Mailbox {
            capacity: capacity as usize,
            queue: Mutex::new(Queue { samples: VecDeque::with_capacity(capacity as usize), closed: false, overflowed: 0 }),
            ready: Condvar::new(),
        });
        Ok(into_handle(mailbox))
    })
}

/// Waits up to `timeout_ns` for a sample and copies it into `payload` and `attachment`.
/// Writes into `info[0]` the channel, `info[1]` the payload length and `info[2]` the attachment
/// length (-1 for none) of the sample taken. Returns 1 when a sample was copied, 0 on timeout,
/// -1 when the sample did not fit (it is dropped, its lengths are reported), -2 when the mailbox
/// was closed. Bytes beyond a buffer's capacity are never written.
#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_take(
    mut env: JNIEnv,
    _class: JClass,
    mailbox: jlong,
    timeout_ns: jlong,
    payload: JByteBuffer,
    attachment: JByteBuffer,
    info: JByteBuffer,
) -> jint {
    guarded(&mut env, -2, |env| {
        let mailbox = unsafe { borrow::<Arc<Mailbox>>(mailbox)? };
        let payload_dst = direct(env, &payload)?;
        let attachment_dst = direct(env, &attachment)?;
        let info_dst = direct(env, &info)?;
        if info_dst.len() < 12 {
            return Err("info buffer needs 12 bytes".to_string());
        }
        let sample = {
            let mut queue = mailbox.queue.lock().unwrap_or_else(|p| p.into_inner());
            if queue.samples.is_empty() && !queue.closed && timeout_ns > 0 {
                let (guard, _) = mailbox
                    .ready
                    .wait_timeout_while(queue, Duration::from_nanos(timeout_ns as u64), |q| q.samples.is_empty() && !q.closed)
                    .unwrap_or_else(|p| p.into_inner());
                queue = guard;
            }
            if queue.closed {
                return Ok(-2);
            }
            match queue.samples.pop_front() {
                Some(sample) => sample,
                None => return Ok(0),
            }
        };
        let attachment_length = sample.attachment.as_ref().map_or(-1, |a| a.len() as i64);
        let write = |dst: &mut [u8], at: usize, value: i64| {
            dst[at..at + 4].copy_from_slice(&(value.clamp(i32::MIN as i64, i32::MAX as i64) as i32).to_le_bytes());
        };
        write(info_dst, 0, sample.channel as i64);
        write(info_dst, 4, sample.payload.len() as i64);
        write(info_dst, 8, attachment_length);
        let attachment_fits = sample.attachment.as_ref().map_or(true, |a| a.len() <= attachment_dst.len());
        if sample.payload.len() > payload_dst.len() || !attachment_fits {
            return Ok(-1);
        }
        payload_dst[..sample.payload.len()].copy_from_slice(&sample.payload);
        if let Some(a) = &sample.attachment {
            attachment_dst[..a.len()].copy_from_slice(a);
        }
        Ok(1)
    })
}

/// Samples dropped because the mailbox was full.
#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_overflowed(mut env: JNIEnv, _class: JClass, mailbox: jlong) -> jlong {
    guarded(&mut env, 0, |_| {
        let mailbox = unsafe { borrow::<Arc<Mailbox>>(mailbox)? };
        let queue = mailbox.queue.lock().unwrap_or_else(|p| p.into_inner());
        Ok(queue.overflowed as jlong)
    })
}

/// Wakes a waiting `take` and makes every later one return -2; frees the mailbox's memory once
/// its subscribers are undeclared too.
#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_closeMailbox(mut env: JNIEnv, _class: JClass, mailbox: jlong) {
    guarded(&mut env, (), |_| {
        if mailbox != 0 {
            let mailbox = unsafe { Box::from_raw(mailbox as *mut Arc<Mailbox>) };
            let mut queue = mailbox.queue.lock().unwrap_or_else(|p| p.into_inner());
            queue.closed = true;
            queue.samples.clear();
            mailbox.ready.notify_all();
        }
        Ok(())
    })
}

/// Subscribes to `key`; its samples go to `mailbox` tagged with `channel`.
#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_declareSubscriber(
    mut env: JNIEnv,
    _class: JClass,
    session: jlong,
    key: JString,
    mailbox: jlong,
    channel: jint,
) -> jlong {
    guarded(&mut env, 0, |env| {
        let session = unsafe { borrow::<Session>(session)? };
        let mailbox = Arc::clone(unsafe { borrow::<Arc<Mailbox>>(mailbox)? });
        let key = key_expr(java_string(env, &key)?)?;
        let subscriber = session
            .declare_subscriber(key)
            .callback(move |sample| {
                mailbox.offer(Sample {
                    channel,
                    payload: sample.payload().to_bytes().into_owned(),
                    attachment: sample.attachment().map(|a| a.to_bytes().into_owned()),
                });
            })
            .wait()
            .map_err(|e| format!("declaring a subscriber: {e}"))?;
        Ok(into_handle(subscriber))
    })
}

#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_undeclareSubscriber(mut env: JNIEnv, _class: JClass, subscriber: jlong) {
    guarded(&mut env, (), |_| {
        if subscriber != 0 {
            let subscriber = unsafe { Box::from_raw(subscriber as *mut Subscriber<()>) };
            subscriber.undeclare().wait().map_err(|e| format!("undeclaring a subscriber: {e}"))?;
        }
        Ok(())
    })
}

// ---------------------------------------------------------------------------------------------
// Liveliness

#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_declareToken(
    mut env: JNIEnv,
    _class: JClass,
    session: jlong,
    key: JString,
) -> jlong {
    guarded(&mut env, 0, |env| {
        let session = unsafe { borrow::<Session>(session)? };
        let key = key_expr(java_string(env, &key)?)?;
        let token = session.liveliness().declare_token(key).wait().map_err(|e| format!("declaring a liveliness token: {e}"))?;
        Ok(into_handle(token))
    })
}

#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_undeclareToken(mut env: JNIEnv, _class: JClass, token: jlong) {
    guarded(&mut env, (), |_| {
        if token != 0 {
            let token = unsafe { Box::from_raw(token as *mut LivelinessToken) };
            token.undeclare().wait().map_err(|e| format!("undeclaring a liveliness token: {e}"))?;
        }
        Ok(())
    })
}

/// The key expressions of the liveliness tokens alive now that match `key`, waiting at most
/// `timeout_ms` for the replies.
#[no_mangle]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_livelinessGet(
    mut env: JNIEnv,
    _class: JClass,
    session: jlong,
    key: JString,
    timeout_ms: jlong,
) -> jobjectArray {
    guarded(&mut env, std::ptr::null_mut(), |env| {
        let session = unsafe { borrow::<Session>(session)? };
        let key = key_expr(java_string(env, &key)?)?;
        let replies = session
            .liveliness()
            .get(key)
            .timeout(Duration::from_millis(timeout_ms.max(0) as u64))
            .wait()
            .map_err(|e| format!("liveliness query: {e}"))?;
        let mut keys = Vec::new();
        while let Ok(reply) = replies.recv() {
            if let Ok(sample) = reply.result() {
                keys.push(sample.key_expr().as_str().to_string());
            }
        }
        let array = env.new_object_array(keys.len() as jint, "java/lang/String", JObject::null()).map_err(|e| e.to_string())?;
        for (i, k) in keys.iter().enumerate() {
            let s = env.new_string(k).map_err(|e| e.to_string())?;
            env.set_object_array_element(&array, i as jint, s).map_err(|e| e.to_string())?;
        }
        Ok(array.into_raw())
    })
}
