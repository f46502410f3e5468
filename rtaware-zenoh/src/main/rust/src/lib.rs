//! The JNI layer between rtaware's Java classes (`io.rtaware.zenoh.NativeZenoh`) and the official
//! Zenoh implementation. It only forwards: every decision (configuration, key expressions, what to
//! do with a sample) is taken on the Java side.
//!
//! Java holds every Rust object by a number in one table ([`handles`]), never by its address: a
//! call looks the number up and keeps the object alive until it returns, and closing takes the
//! number out of the table, so a double close, a use after close or a close racing a waiting
//! `take` ends in a `ZenohException` or a defined result, never in freed memory. Samples of
//! subscribers reach Java through a [`mailbox`]: the subscriber callbacks (Zenoh's threads) append
//! owned copies to a bounded queue, and a Java thread takes them one at a time, copying payload
//! and attachment into direct buffers that Java allocated once, so the Java side allocates
//! nothing per sample.

mod handles;
mod mailbox;
mod messages;

use std::sync::Arc;
use std::time::Duration;

use handles::{release, Handles};
use mailbox::{Mailbox, Sample, CLOSED};

use jni::objects::{JByteBuffer, JClass, JObject, JObjectArray, JString};
use jni::sys::{jboolean, jint, jlong, jobjectArray, jstring, JNI_TRUE};
use jni::JNIEnv;
use zenoh::key_expr::KeyExpr;
use zenoh::liveliness::LivelinessToken;
use zenoh::pubsub::{Publisher, Subscriber};
use zenoh::{Config, Session, Wait};

const ZENOH_EXCEPTION: &str = "io/rtaware/zenoh/ZenohException";

/// Every object Java holds.
static HANDLES: Handles = Handles::new();

/// Runs `body`, turning an error or a panic into a `ZenohException` and `fallback`.
fn guarded<T>(env: &mut JNIEnv, fallback: T, body: impl FnOnce(&mut JNIEnv) -> Result<T, String>) -> T {
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| body(env)));
    match outcome {
        Ok(Ok(value)) => value,
        Ok(Err(message)) => {
            let _ = env.throw_new(ZENOH_EXCEPTION, messages::without_source_locations(&message));
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

/// Runs `body` in a JNI local frame of its own: the local references it creates are freed when it
/// returns, so that a loop over an array's elements holds one element's at a time (a native
/// method may otherwise hold only 16, and they would pile up until it returns).
fn in_local_frame<T>(env: &mut JNIEnv, body: impl FnOnce(&mut JNIEnv) -> Result<T, String>) -> Result<T, String> {
    env.with_local_frame(LOCALS_PER_ELEMENT, |env| Ok::<_, jni::errors::Error>(body(env)))
        .map_err(|e| format!("JNI local frame: {e}"))?
}

/// The local references one element of a string array takes: the element, a spare.
const LOCALS_PER_ELEMENT: i32 = 2;

fn java_strings(env: &mut JNIEnv, array: &JObjectArray) -> Result<Vec<String>, String> {
    let n = env.get_array_length(array).map_err(|e| e.to_string())?;
    let mut out = Vec::with_capacity(n as usize);
    for i in 0..n {
        out.push(in_local_frame(env, |env| {
            let element = env.get_object_array_element(array, i).map_err(|e| e.to_string())?;
            java_string(env, &JString::from(element))
        })?);
    }
    Ok(out)
}

/// A new Java `String[]` holding `values`: one local reference, the array, returned to Java.
fn string_array(env: &mut JNIEnv, values: &[String]) -> Result<jobjectArray, String> {
    let array = env.new_object_array(values.len() as jint, "java/lang/String", JObject::null()).map_err(|e| e.to_string())?;
    for (i, value) in values.iter().enumerate() {
        in_local_frame(env, |env| {
            let s = env.new_string(value).map_err(|e| e.to_string())?;
            env.set_object_array_element(&array, i as jint, s).map_err(|e| e.to_string())
        })?;
    }
    Ok(array.into_raw())
}

fn json_strings(values: &[String]) -> String {
    let quoted: Vec<String> = values.iter().map(|v| format!("{:?}", v)).collect();
    format!("[{}]", quoted.join(","))
}

/// A direct buffer's address and capacity.
fn direct_memory(env: &mut JNIEnv, buffer: &JByteBuffer) -> Result<(*mut u8, usize), String> {
    let address = env.get_direct_buffer_address(buffer).map_err(|e| format!("not a direct buffer: {e}"))?;
    let capacity = env.get_direct_buffer_capacity(buffer).map_err(|e| format!("not a direct buffer: {e}"))?;
    Ok((address, capacity))
}

/// A direct buffer's memory, to read (several such views may share memory).
fn direct<'a>(env: &mut JNIEnv, buffer: &JByteBuffer) -> Result<&'a [u8], String> {
    let (address, capacity) = direct_memory(env, buffer)?;
    // SAFETY: the JVM guarantees `capacity` bytes at `address` while the buffer is reachable,
    // and the Java caller keeps it reachable for the duration of the call.
    Ok(unsafe { std::slice::from_raw_parts(address, capacity) })
}

/// The memory of three direct buffers to write, refused when any two of them overlap (two
/// mutable views of the same bytes are not allowed in Rust).
fn direct_disjoint<'a>(env: &mut JNIEnv, buffers: [&JByteBuffer; 3]) -> Result<[&'a mut [u8]; 3], String> {
    let [a, b, c] = buffers;
    let memory = [direct_memory(env, a)?, direct_memory(env, b)?, direct_memory(env, c)?];
    if any_overlap(&memory.map(|(address, capacity)| (address as usize, capacity))) {
        return Err("the payload, attachment and info buffers must not share memory".to_string());
    }
    // SAFETY: as in `direct`; the three ranges are disjoint, so the mutable views do not alias.
    Ok(memory.map(|(address, capacity)| unsafe { std::slice::from_raw_parts_mut(address, capacity) }))
}

/// Whether any two of the (start, length) ranges share a byte.
fn any_overlap(ranges: &[(usize, usize)]) -> bool {
    (0..ranges.len()).any(|i| {
        (i + 1..ranges.len()).any(|j| {
            let ((start_i, length_i), (start_j, length_j)) = (ranges[i], ranges[j]);
            start_i < start_j + length_j && start_j < start_i + length_i
        })
    })
}

fn key_expr(text: String) -> Result<KeyExpr<'static>, String> {
    KeyExpr::try_from(text.clone()).map_err(|e| format!("invalid key expression '{text}': {e}"))
}


// ---------------------------------------------------------------------------------------------
// Session

/// Opens a session. `mode` is "peer" or "client"; endpoints are Zenoh locators
/// (`tcp/127.0.0.1:7447`); `connect_timeout_ms` bounds the wait for the connect endpoints, and
/// with at least one connect endpoint the open fails when none can be reached in that time.
#[unsafe(no_mangle)]
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
        Ok(HANDLES.insert(session))
    })
}

/// The session's Zenoh id as Zenoh prints it (lowercase hexadecimal).
#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_zid(mut env: JNIEnv, _class: JClass, session: jlong) -> jstring {
    guarded(&mut env, std::ptr::null_mut(), |env| {
        let session = HANDLES.get::<Session>(session, "session")?;
        let zid = session.zid().to_string();
        env.new_string(zid).map(JString::into_raw).map_err(|e| e.to_string())
    })
}

#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_close(mut env: JNIEnv, _class: JClass, session: jlong) {
    guarded(&mut env, (), |_| {
        // Zenoh closes a session through a shared reference: calls still using it get Zenoh's
        // "closed" errors, and its memory goes with the last of them.
        let session = HANDLES.remove::<Session>(session, "session")?;
        session.close().wait().map_err(|e| format!("closing the Zenoh session: {e}"))
    })
}

// ---------------------------------------------------------------------------------------------
// Publisher

#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_declarePublisher(
    mut env: JNIEnv,
    _class: JClass,
    session: jlong,
    key: JString,
) -> jlong {
    guarded(&mut env, 0, |env| {
        let session = HANDLES.get::<Session>(session, "session")?;
        let key = key_expr(java_string(env, &key)?)?;
        let publisher = session.declare_publisher(key).wait().map_err(|e| format!("declaring a publisher: {e}"))?;
        Ok(HANDLES.insert(publisher))
    })
}

/// Publishes the first `length` bytes of `payload` with the first `attachment_length` bytes of
/// `attachment` (no attachment when `attachment_length` is negative).
#[unsafe(no_mangle)]
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
        let publisher = HANDLES.get::<Publisher<'static>>(publisher, "publisher")?;
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

#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_undeclarePublisher(mut env: JNIEnv, _class: JClass, publisher: jlong) {
    guarded(&mut env, (), |_| {
        let publisher = HANDLES.remove::<Publisher<'static>>(publisher, "publisher")?;
        release(publisher, |p| p.undeclare().wait().map_err(|e| format!("undeclaring a publisher: {e}")))
    })
}

// ---------------------------------------------------------------------------------------------
// Mailbox and subscribers

#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_newMailbox(mut env: JNIEnv, _class: JClass, capacity: jint) -> jlong {
    guarded(&mut env, 0, |_| {
        Ok(HANDLES.insert(Mailbox::new(capacity)?))
    })
}

/// Waits up to `timeout_ns` for a sample and copies it into `payload` and `attachment`
/// ([`Mailbox::take`]). Writes into `info[0]` the channel, `info[1]` the payload length and
/// `info[2]` the attachment length (-1 for none) of the sample taken. Returns 1 when a sample was
/// copied, 0 on timeout, -1 when the sample did not fit (it is dropped, its lengths are reported),
/// -2 when the mailbox was closed while or before waiting; throws when the handle is closed.
/// Bytes beyond a buffer's capacity are never written.
#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_take(
    mut env: JNIEnv,
    _class: JClass,
    mailbox: jlong,
    timeout_ns: jlong,
    payload: JByteBuffer,
    attachment: JByteBuffer,
    info: JByteBuffer,
) -> jint {
    guarded(&mut env, CLOSED, |env| {
        // Our own reference: a concurrent closeMailbox wakes this wait, but cannot free it.
        let mailbox = HANDLES.get::<Mailbox>(mailbox, "mailbox")?;
        let [payload_dst, attachment_dst, info_dst] = direct_disjoint(env, [&payload, &attachment, &info])?;
        mailbox.take(timeout_ns, payload_dst, attachment_dst, info_dst)
    })
}

/// Samples dropped because the mailbox was full.
#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_overflowed(mut env: JNIEnv, _class: JClass, mailbox: jlong) -> jlong {
    guarded(&mut env, 0, |_| Ok(HANDLES.get::<Mailbox>(mailbox, "mailbox")?.overflowed() as jlong))
}

/// Wakes a waiting `take` (which returns -2) and makes every later call with this handle throw.
/// The memory goes with the last reference: a `take` still returning, or a subscriber callback
/// (its subscriber not yet undeclared).
#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_closeMailbox(mut env: JNIEnv, _class: JClass, mailbox: jlong) {
    guarded(&mut env, (), |_| {
        HANDLES.remove::<Mailbox>(mailbox, "mailbox")?.close();
        Ok(())
    })
}

/// Subscribes to `key`; its samples go to `mailbox` tagged with `channel`.
#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_declareSubscriber(
    mut env: JNIEnv,
    _class: JClass,
    session: jlong,
    key: JString,
    mailbox: jlong,
    channel: jint,
) -> jlong {
    guarded(&mut env, 0, |env| {
        let session = HANDLES.get::<Session>(session, "session")?;
        let mailbox: Arc<Mailbox> = HANDLES.get::<Mailbox>(mailbox, "mailbox")?;
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
        Ok(HANDLES.insert(subscriber))
    })
}

#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_undeclareSubscriber(mut env: JNIEnv, _class: JClass, subscriber: jlong) {
    guarded(&mut env, (), |_| {
        let subscriber = HANDLES.remove::<Subscriber<()>>(subscriber, "subscriber")?;
        release(subscriber, |s| s.undeclare().wait().map_err(|e| format!("undeclaring a subscriber: {e}")))
    })
}

// ---------------------------------------------------------------------------------------------
// Liveliness

#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_declareToken(
    mut env: JNIEnv,
    _class: JClass,
    session: jlong,
    key: JString,
) -> jlong {
    guarded(&mut env, 0, |env| {
        let session = HANDLES.get::<Session>(session, "session")?;
        let key = key_expr(java_string(env, &key)?)?;
        let token = session.liveliness().declare_token(key).wait().map_err(|e| format!("declaring a liveliness token: {e}"))?;
        Ok(HANDLES.insert(token))
    })
}

#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_undeclareToken(mut env: JNIEnv, _class: JClass, token: jlong) {
    guarded(&mut env, (), |_| {
        let token = HANDLES.remove::<LivelinessToken>(token, "liveliness token")?;
        release(token, |t| t.undeclare().wait().map_err(|e| format!("undeclaring a liveliness token: {e}")))
    })
}

/// The key expressions of the liveliness tokens alive now that match `key`, waiting at most
/// `timeout_ms` for the replies. More than `max_keys` of them is an error naming the pattern
/// (the query stops there): the answer's size is the network's to choose, not this process's.
#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_livelinessGet(
    mut env: JNIEnv,
    _class: JClass,
    session: jlong,
    key: JString,
    timeout_ms: jlong,
    max_keys: jint,
) -> jobjectArray {
    guarded(&mut env, std::ptr::null_mut(), |env| {
        let session = HANDLES.get::<Session>(session, "session")?;
        let pattern = java_string(env, &key)?;
        let replies = session
            .liveliness()
            .get(key_expr(pattern.clone())?)
            .timeout(Duration::from_millis(timeout_ms.max(0) as u64))
            .wait()
            .map_err(|e| format!("liveliness query: {e}"))?;
        let keys = at_most(max_keys.max(0) as usize, std::iter::from_fn(|| replies.recv().ok()).filter_map(|reply| {
            reply.result().ok().map(|sample| sample.key_expr().as_str().to_string())
        }))
        .map_err(|max| format!("more than {max} liveliness tokens match '{pattern}'"))?;
        string_array(env, &keys)
    })
}

/// A query (`session.get`) on `selector`: the replies that arrive within the timeout, each as its key
/// followed by its payload read as UTF-8 (invalid bytes replaced), flattened into one array
/// (`key0, text0, key1, text1, ...`); error replies are left out. At most `max_replies`, and no
/// reply's payload above `max_reply_bytes` (what an admin space answers is a little JSON).
#[unsafe(no_mangle)]
pub extern "system" fn Java_io_rtaware_zenoh_NativeZenoh_get(
    mut env: JNIEnv,
    _class: JClass,
    session: jlong,
    selector: JString,
    timeout_ms: jlong,
    max_replies: jint,
    max_reply_bytes: jint,
) -> jobjectArray {
    guarded(&mut env, std::ptr::null_mut(), |env| {
        let session = HANDLES.get::<Session>(session, "session")?;
        let selector = java_string(env, &selector)?;
        let replies = session
            .get(key_expr(selector.clone())?)
            .timeout(Duration::from_millis(timeout_ms.max(0) as u64))
            .wait()
            .map_err(|e| format!("query: {e}"))?;
        let max_bytes = max_reply_bytes.max(0) as usize;
        let samples = at_most(
            max_replies.max(0) as usize,
            std::iter::from_fn(|| replies.recv().ok()).filter_map(|reply| reply.into_result().ok()),
        )
        .map_err(|max| format!("more than {max} replies to '{selector}'"))?;
        let mut flat = Vec::with_capacity(samples.len() * 2);
        for sample in samples {
            let length = sample.payload().len();
            if length > max_bytes {
                return Err(format!("a reply of {length} bytes to '{selector}' exceeds the largest accepted ({max_bytes})"));
            }
            flat.push(sample.key_expr().as_str().to_string());
            flat.push(String::from_utf8_lossy(&sample.payload().to_bytes()).into_owned());
        }
        string_array(env, &flat)
    })
}

/// The items of `items`, or `Err(max)` as soon as there are more than `max` (the rest is not read).
fn at_most<T>(max: usize, items: impl Iterator<Item = T>) -> Result<Vec<T>, usize> {
    let mut out = Vec::new();
    for item in items {
        if out.len() == max {
            return Err(max);
        }
        out.push(item);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::{any_overlap, at_most};

    #[test]
    fn at_most_stops_reading_at_the_first_item_too_many() {
        assert_eq!(at_most(3, 0..3), Ok(vec![0, 1, 2]));
        assert_eq!(at_most(0, 0..0), Ok(vec![]));
        let mut read = 0;
        assert_eq!(at_most(3, (0..1_000_000).inspect(|_| read += 1)), Err(3));
        assert_eq!(read, 4, "three kept, the fourth refused, nothing after it read");
    }

    #[test]
    fn buffers_sharing_a_byte_overlap_and_adjacent_ones_do_not() {
        assert!(!any_overlap(&[(0, 16), (16, 4), (20, 12)]), "adjacent");
        assert!(any_overlap(&[(0, 16), (100, 4), (0, 16)]), "the same buffer twice");
        assert!(any_overlap(&[(0, 16), (8, 8), (100, 12)]), "a slice of the first");
        assert!(any_overlap(&[(100, 4), (0, 16), (15, 1)]), "the last byte");
        assert!(!any_overlap(&[(0, 0), (0, 16), (200, 12)]), "an empty buffer shares nothing");
    }
}
