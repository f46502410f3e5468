//! Where subscribers deliver samples: a bounded queue filled by Zenoh's threads and emptied by a
//! Java thread, which copies one sample at a time into buffers it allocated once.

use std::collections::VecDeque;
use std::sync::{Condvar, Mutex};
use std::time::Duration;

/// One received sample, owned.
pub struct Sample {
    pub channel: i32,
    pub payload: Vec<u8>,
    pub attachment: Option<Vec<u8>>,
}

struct Queue {
    samples: VecDeque<Sample>,
    closed: bool,
    overflowed: u64,
}

/// What [`Mailbox::take`] found, as the Java side numbers it.
pub const TAKEN: i32 = 1;
/// Nothing arrived in time.
pub const TIMEOUT: i32 = 0;
/// The sample did not fit the buffers: dropped, its lengths reported.
pub const TOO_LARGE: i32 = -1;
/// The mailbox was closed (before or during the wait).
pub const CLOSED: i32 = -2;
/// Bytes of the info buffer: channel, payload length, attachment length (little-endian i32).
pub const INFO_BYTES: usize = 12;

/// A bounded queue. When it is full the oldest sample is dropped (and counted): for sensor data
/// the newest value matters. Shared (`Arc`) by the handle table, its subscribers' callbacks and
/// the calls using it.
pub struct Mailbox {
    capacity: usize,
    queue: Mutex<Queue>,
    ready: Condvar,
}

impl Mailbox {
    /// A mailbox keeping at most `capacity` samples (positive).
    pub fn new(capacity: i32) -> Result<Mailbox, String> {
        if capacity <= 0 {
            return Err(format!("mailbox capacity {capacity} must be positive"));
        }
        let capacity = capacity as usize;
        Ok(Mailbox {
            capacity,
            queue: Mutex::new(Queue { samples: VecDeque::with_capacity(capacity), closed: false, overflowed: 0 }),
            ready: Condvar::new(),
        })
    }

    /// Appends a sample (dropping the oldest when full); ignored once closed.
    pub fn offer(&self, sample: Sample) {
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

    /// Samples dropped because the mailbox was full.
    pub fn overflowed(&self) -> u64 {
        self.queue.lock().unwrap_or_else(|p| p.into_inner()).overflowed
    }

    /// Wakes every waiting `take` and makes it and every later one return [`CLOSED`]; drops the
    /// samples still queued. Idempotent.
    pub fn close(&self) {
        let mut queue = self.queue.lock().unwrap_or_else(|p| p.into_inner());
        queue.closed = true;
        queue.samples.clear();
        self.ready.notify_all();
    }

    /// Waits up to `timeout_ns` (0 or less: not at all) for a sample and copies it into `payload`
    /// and `attachment`. Writes into `info` the channel, the payload length and the attachment
    /// length (-1 for none) of the sample taken, also when it did not fit. Returns [`TAKEN`],
    /// [`TIMEOUT`], [`TOO_LARGE`] or [`CLOSED`]. Bytes beyond a buffer's length are never written.
    pub fn take(&self, timeout_ns: i64, payload: &mut [u8], attachment: &mut [u8], info: &mut [u8]) -> Result<i32, String> {
        if info.len() < INFO_BYTES {
            return Err(format!("info buffer needs {INFO_BYTES} bytes, has {}", info.len()));
        }
        let sample = {
            let mut queue = self.queue.lock().unwrap_or_else(|p| p.into_inner());
            if queue.samples.is_empty() && !queue.closed && timeout_ns > 0 {
                let (guard, _) = self
                    .ready
                    .wait_timeout_while(queue, Duration::from_nanos(timeout_ns as u64), |q| q.samples.is_empty() && !q.closed)
                    .unwrap_or_else(|p| p.into_inner());
                queue = guard;
            }
            if queue.closed {
                return Ok(CLOSED);
            }
            match queue.samples.pop_front() {
                Some(sample) => sample,
                None => return Ok(TIMEOUT),
            }
        };
        let attachment_length = sample.attachment.as_ref().map_or(-1, |a| a.len() as i64);
        write_i32(info, 0, sample.channel as i64);
        write_i32(info, 4, sample.payload.len() as i64);
        write_i32(info, 8, attachment_length);
        let attachment_fits = sample.attachment.as_ref().map_or(true, |a| a.len() <= attachment.len());
        if sample.payload.len() > payload.len() || !attachment_fits {
            return Ok(TOO_LARGE);
        }
        payload[..sample.payload.len()].copy_from_slice(&sample.payload);
        if let Some(a) = &sample.attachment {
            attachment[..a.len()].copy_from_slice(a);
        }
        Ok(TAKEN)
    }
}

fn write_i32(dst: &mut [u8], at: usize, value: i64) {
    let clamped = value.clamp(i32::MIN as i64, i32::MAX as i64) as i32;
    dst[at..at + 4].copy_from_slice(&clamped.to_le_bytes());
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::handles::Handles;
    use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
    use std::sync::Arc;

    fn sample(channel: i32, payload: &[u8], attachment: Option<&[u8]>) -> Sample {
        Sample { channel, payload: payload.to_vec(), attachment: attachment.map(<[u8]>::to_vec) }
    }

    fn info_of(info: &[u8]) -> (i32, i32, i32) {
        let at = |i: usize| i32::from_le_bytes(info[i..i + 4].try_into().unwrap());
        (at(0), at(4), at(8))
    }

    #[test]
    fn a_sample_is_copied_with_its_channel_and_lengths_and_nothing_beyond() {
        let mailbox = Mailbox::new(4).unwrap();
        mailbox.offer(sample(7, &[1, 2, 3], Some(&[9])));
        let (mut payload, mut attachment, mut info) = ([0xAAu8; 8], [0xAAu8; 4], [0u8; INFO_BYTES]);
        assert_eq!(mailbox.take(0, &mut payload, &mut attachment, &mut info), Ok(TAKEN));
        assert_eq!(info_of(&info), (7, 3, 1));
        assert_eq!(payload, [1, 2, 3, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA], "bytes after the payload untouched");
        assert_eq!(attachment, [9, 0xAA, 0xAA, 0xAA]);
    }

    #[test]
    fn a_sample_without_attachment_reports_minus_one() {
        let mailbox = Mailbox::new(1).unwrap();
        mailbox.offer(sample(0, &[5], None));
        let (mut payload, mut attachment, mut info) = ([0u8; 1], [0u8; 1], [0u8; INFO_BYTES]);
        assert_eq!(mailbox.take(0, &mut payload, &mut attachment, &mut info), Ok(TAKEN));
        assert_eq!(info_of(&info), (0, 1, -1));
    }

    #[test]
    fn a_payload_or_attachment_too_large_is_dropped_with_its_lengths_and_nothing_written() {
        let mailbox = Mailbox::new(4).unwrap();
        mailbox.offer(sample(1, &[1; 100], None));
        mailbox.offer(sample(2, &[1; 4], Some(&[2; 9])));
        mailbox.offer(sample(3, &[1; 4], Some(&[2; 8])));
        let (mut payload, mut attachment, mut info) = ([0u8; 4], [0u8; 8], [0u8; INFO_BYTES]);
        assert_eq!(mailbox.take(0, &mut payload, &mut attachment, &mut info), Ok(TOO_LARGE));
        assert_eq!(info_of(&info), (1, 100, -1));
        assert_eq!(payload, [0; 4], "a sample that does not fit writes no payload byte");
        assert_eq!(mailbox.take(0, &mut payload, &mut attachment, &mut info), Ok(TOO_LARGE));
        assert_eq!(info_of(&info), (2, 4, 9));
        assert_eq!(attachment, [0; 8]);
        assert_eq!(mailbox.take(0, &mut payload, &mut attachment, &mut info), Ok(TAKEN), "exactly full fits");
        assert_eq!(info_of(&info), (3, 4, 8));
        assert_eq!(mailbox.take(0, &mut payload, &mut attachment, &mut info), Ok(TIMEOUT));
    }

    #[test]
    fn a_full_mailbox_drops_the_oldest_and_counts_each() {
        let mailbox = Mailbox::new(2).unwrap();
        for i in 0..5u8 {
            mailbox.offer(sample(0, &[i], None));
        }
        assert_eq!(mailbox.overflowed(), 3);
        let (mut payload, mut attachment, mut info) = ([0u8; 1], [0u8; 1], [0u8; INFO_BYTES]);
        mailbox.take(0, &mut payload, &mut attachment, &mut info).unwrap();
        assert_eq!(payload[0], 3, "the oldest go first");
        mailbox.take(0, &mut payload, &mut attachment, &mut info).unwrap();
        assert_eq!(payload[0], 4);
    }

    #[test]
    fn a_closed_mailbox_returns_closed_drops_its_samples_and_ignores_new_ones() {
        let mailbox = Mailbox::new(2).unwrap();
        mailbox.offer(sample(0, &[1], None));
        mailbox.close();
        mailbox.offer(sample(0, &[2], None));
        mailbox.close();
        let (mut payload, mut attachment, mut info) = ([0u8; 1], [0u8; 1], [0u8; INFO_BYTES]);
        assert_eq!(mailbox.take(1_000_000_000, &mut payload, &mut attachment, &mut info), Ok(CLOSED));
        assert_eq!(payload[0], 0);
    }

    #[test]
    fn bad_arguments_are_errors() {
        assert!(Mailbox::new(0).is_err());
        assert!(Mailbox::new(-3).is_err());
        let mailbox = Mailbox::new(1).unwrap();
        let (mut payload, mut attachment, mut info) = ([0u8; 1], [0u8; 1], [0u8; INFO_BYTES - 1]);
        assert!(mailbox.take(0, &mut payload, &mut attachment, &mut info).is_err());
    }

    #[test]
    fn a_waiting_take_is_woken_by_a_sample() {
        let mailbox = Arc::new(Mailbox::new(1).unwrap());
        let reader = {
            let mailbox = mailbox.clone();
            std::thread::spawn(move || {
                let (mut payload, mut attachment, mut info) = ([0u8; 1], [0u8; 1], [0u8; INFO_BYTES]);
                let r = mailbox.take(i64::MAX, &mut payload, &mut attachment, &mut info);
                (r, payload[0])
            })
        };
        mailbox.offer(sample(0, &[42], None));
        assert_eq!(reader.join().unwrap(), (Ok(TAKEN), 42));
    }

    /// The race the JNI layer used to leave to a Java comment: the mailbox is closed (its handle
    /// removed and released, its subscriber undeclared) while a reader waits in `take` and a
    /// Zenoh thread still offers. Every take must end in a sample, a timeout, CLOSED, or a
    /// "closed" error for a handle already gone; the memory must outlive every user.
    #[test]
    fn closing_races_take_and_offer_without_a_use_after_free() {
        let handles = Arc::new(Handles::new());
        let outcomes = Arc::new([AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0)]);
        for round in 0..2_000u64 {
            let handle = handles.insert(Mailbox::new(4).unwrap());
            let subscriber = handles.get::<Mailbox>(handle, "mailbox").unwrap();
            let stop = Arc::new(AtomicBool::new(false));
            let writer = {
                let stop = stop.clone();
                std::thread::spawn(move || {
                    let mut i = 0u8;
                    while !stop.load(Ordering::Relaxed) {
                        subscriber.offer(sample(1, &[i; 16], Some(&[i; 2])));
                        i = i.wrapping_add(1);
                    }
                })
            };
            let readers: Vec<_> = (0..2)
                .map(|_| {
                    let handles = handles.clone();
                    let outcomes = outcomes.clone();
                    std::thread::spawn(move || loop {
                        let (mut payload, mut attachment, mut info) = ([0u8; 16], [0u8; 2], [0u8; INFO_BYTES]);
                        let taken = handles
                            .get::<Mailbox>(handle, "mailbox")
                            .and_then(|m| m.take(50_000, &mut payload, &mut attachment, &mut info));
                        match taken {
                            Ok(TAKEN) => {
                                assert!(payload.iter().all(|b| *b == payload[0]), "a torn sample: {payload:?}");
                                outcomes[0].fetch_add(1, Ordering::Relaxed);
                            }
                            Ok(TIMEOUT) => {
                                outcomes[1].fetch_add(1, Ordering::Relaxed);
                            }
                            Ok(CLOSED) => {
                                outcomes[2].fetch_add(1, Ordering::Relaxed);
                                return;
                            }
                            Err(e) => {
                                assert!(e.contains("closed"), "{e}");
                                outcomes[3].fetch_add(1, Ordering::Relaxed);
                                return;
                            }
                            Ok(other) => panic!("take returned {other}"),
                        }
                    })
                })
                .collect();
            if round % 3 != 0 {
                std::thread::yield_now();
            }
            let mailbox = handles.remove::<Mailbox>(handle, "mailbox").unwrap();
            mailbox.close();
            drop(mailbox);
            for reader in readers {
                reader.join().expect("a reader failed");
            }
            stop.store(true, Ordering::Relaxed);
            writer.join().unwrap();
        }
        assert_eq!(handles.len(), 0);
        let seen: Vec<u64> = outcomes.iter().map(|o| o.load(Ordering::Relaxed)).collect();
        assert_eq!(seen[2] + seen[3], 4_000, "every reader ended on the close: {seen:?}");
        assert!(seen[2] > 0, "some readers must have been woken inside take: {seen:?}");
    }
}
