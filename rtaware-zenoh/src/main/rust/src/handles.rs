//! The table of objects that Java holds by number.
//!
//! Java never sees an address: every session, publisher, mailbox, subscriber and liveliness token
//! lives in this table under a number that is never used again, and each native call looks the
//! number up and takes its own reference (`Arc`) for the length of the call. Closing removes the
//! entry, so a later call with the same number (a use after close, a double close, a number of
//! another kind) finds nothing and fails with a message instead of touching freed memory; the
//! object itself is freed when the last call still using it returns.

use std::any::Any;
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicI64, Ordering};
use std::sync::{Arc, RwLock};

type Entry = Arc<dyn Any + Send + Sync>;

/// Objects by handle. Thread-safe: lookups share a read lock held only for the lookup itself.
pub struct Handles {
    next: AtomicI64,
    live: RwLock<BTreeMap<i64, Entry>>,
}

impl Handles {
    /// An empty table; its first handle is 1 (0 stands for "none" on the Java side).
    pub const fn new() -> Self {
        Handles { next: AtomicI64::new(1), live: RwLock::new(BTreeMap::new()) }
    }

    /// Keeps `value` and returns its new handle.
    pub fn insert<T: Any + Send + Sync>(&self, value: T) -> i64 {
        let handle = self.next.fetch_add(1, Ordering::Relaxed);
        self.live.write().unwrap_or_else(|p| p.into_inner()).insert(handle, Arc::new(value));
        handle
    }

    /// A reference to the object of `handle`, which must be a `T` (`what` names it in messages).
    pub fn get<T: Any + Send + Sync>(&self, handle: i64, what: &str) -> Result<Arc<T>, String> {
        let entry = {
            let live = self.live.read().unwrap_or_else(|p| p.into_inner());
            live.get(&handle).cloned()
        };
        match entry {
            None => Err(closed(handle, what)),
            Some(entry) => entry.downcast::<T>().map_err(|_| format!("handle {handle} is not a Zenoh {what}")),
        }
    }

    /// Takes the object of `handle` (a `T`) out of the table: later calls with `handle` fail.
    /// Calls already using it keep their reference; the object is freed after the last one.
    pub fn remove<T: Any + Send + Sync>(&self, handle: i64, what: &str) -> Result<Arc<T>, String> {
        let mut live = self.live.write().unwrap_or_else(|p| p.into_inner());
        match live.get(&handle) {
            None => Err(closed(handle, what)),
            Some(entry) if !entry.is::<T>() => Err(format!("handle {handle} is not a Zenoh {what}")),
            Some(_) => {
                let entry = live.remove(&handle).expect("present under the same lock");
                Ok(entry.downcast::<T>().unwrap_or_else(|_| unreachable!("type checked under the same lock")))
            }
        }
    }

    /// Handles in the table now.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.live.read().unwrap_or_else(|p| p.into_inner()).len()
    }
}

fn closed(handle: i64, what: &str) -> String {
    if handle == 0 {
        format!("the Zenoh {what} is closed")
    } else {
        format!("the Zenoh {what} (handle {handle}) is closed or was never opened")
    }
}

/// Runs `undeclare` on the object when `shared` was its last reference, otherwise leaves it to
/// the call still using it, whose reference frees it (Zenoh undeclares on drop) when it returns.
pub fn release<T>(shared: Arc<T>, undeclare: impl FnOnce(T) -> Result<(), String>) -> Result<(), String> {
    match Arc::try_unwrap(shared) {
        Ok(owned) => undeclare(owned),
        Err(still_used) => {
            drop(still_used);
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicUsize;

    struct Counted(Arc<AtomicUsize>);

    impl Drop for Counted {
        fn drop(&mut self) {
            self.0.fetch_add(1, Ordering::SeqCst);
        }
    }

    #[test]
    fn handles_are_never_zero_and_never_reused() {
        let handles = Handles::new();
        let a = handles.insert(1u8);
        handles.remove::<u8>(a, "test").unwrap();
        let b = handles.insert(2u8);
        assert!(a != 0 && b != 0, "0 means none on the Java side");
        assert_ne!(a, b, "a closed handle's number must not name a new object");
    }

    #[test]
    fn a_double_close_and_a_use_after_close_are_errors() {
        let handles = Handles::new();
        let h = handles.insert(String::from("x"));
        handles.remove::<String>(h, "publisher").unwrap();
        let again = handles.remove::<String>(h, "publisher").unwrap_err();
        assert!(again.contains("closed"), "double close: {again}");
        let used = handles.get::<String>(h, "publisher").unwrap_err();
        assert!(used.contains("closed"), "use after close: {used}");
        assert!(handles.get::<String>(0, "session").unwrap_err().contains("closed"));
        assert!(handles.get::<String>(-5, "session").is_err(), "a number never handed out");
    }

    #[test]
    fn a_handle_of_another_kind_is_refused_and_stays_open() {
        let handles = Handles::new();
        let h = handles.insert(7u32);
        let wrong = handles.get::<String>(h, "mailbox").unwrap_err();
        assert!(wrong.contains("not a Zenoh mailbox"), "{wrong}");
        assert!(handles.remove::<String>(h, "mailbox").is_err());
        assert_eq!(*handles.get::<u32>(h, "x").unwrap(), 7, "the refused close must not remove it");
    }

    #[test]
    fn the_object_is_freed_by_the_last_user_not_by_the_close() {
        let drops = Arc::new(AtomicUsize::new(0));
        let handles = Handles::new();
        let h = handles.insert(Counted(drops.clone()));
        let in_use = handles.get::<Counted>(h, "x").unwrap();
        let removed = handles.remove::<Counted>(h, "x").unwrap();
        let mut undeclared = false;
        release(removed, |_| {
            undeclared = true;
            Ok(())
        })
        .unwrap();
        assert!(!undeclared, "still used: undeclaring is left to the last user");
        assert_eq!(drops.load(Ordering::SeqCst), 0, "freed while another call used it");
        drop(in_use);
        assert_eq!(drops.load(Ordering::SeqCst), 1, "the last user frees it");
        assert_eq!(handles.len(), 0);
    }

    #[test]
    fn an_unshared_object_is_undeclared_by_the_close() {
        let drops = Arc::new(AtomicUsize::new(0));
        let handles = Handles::new();
        let h = handles.insert(Counted(drops.clone()));
        let mut undeclared = false;
        release(handles.remove::<Counted>(h, "x").unwrap(), |_| {
            undeclared = true;
            Ok(())
        })
        .unwrap();
        assert!(undeclared);
        assert_eq!(drops.load(Ordering::SeqCst), 1);
    }

    #[test]
    fn concurrent_closes_of_one_handle_succeed_exactly_once() {
        let handles = Arc::new(Handles::new());
        for _ in 0..2_000 {
            let h = handles.insert(0u64);
            let racers: Vec<_> = (0..4)
                .map(|_| {
                    let handles = handles.clone();
                    std::thread::spawn(move || handles.remove::<u64>(h, "x").is_ok())
                })
                .collect();
            let closed = racers.into_iter().map(|t| t.join().unwrap()).filter(|ok| *ok).count();
            assert_eq!(closed, 1, "handle {h} closed {closed} times");
        }
    }
}
