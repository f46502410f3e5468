//! The Cyclone DDS domain, created from a configuration string rather than `CYCLONEDDS_URI`, with
//! what Cyclone DDS logs while creating it captured so that a refusal is one line naming its reason.

use std::ffi::{CStr, CString, c_void};
use std::sync::Mutex;

use cyclors::{dds_create_domain, dds_log_data_t, dds_set_log_sink, dds_strretcode};

/// Cyclone DDS's log categories (`dds/ddsrt/log.h`): fatal, error, warning.
const FATAL: u32 = 1;
const ERROR: u32 = 2;
const WARNING: u32 = 4;

/// What Cyclone DDS logged while the domain was being created: (category, text).
static LOGGED: Mutex<Vec<(u32, String)>> = Mutex::new(Vec::new());

unsafe extern "C" fn capture(_: *mut c_void, data: *const dds_log_data_t) {
    // SAFETY: Cyclone DDS passes a record valid for the duration of the call, whose message
    // holds `size` bytes of text (its header, time and thread, lies before it).
    let data = unsafe { &*data };
    if data.priority & (FATAL | ERROR | WARNING) == 0 || data.message.is_null() {
        return;
    }
    let bytes = unsafe { std::slice::from_raw_parts(data.message.cast::<u8>(), data.size) };
    let text = String::from_utf8_lossy(bytes).trim().to_string();
    if let Ok(mut logged) = LOGGED.lock() {
        logged.push((data.priority, text));
    }
}

/// Creates domain `domain` with `config` (XML fragments and file names, as `CYCLONEDDS_URI` holds
/// them; empty for Cyclone's defaults). The warnings Cyclone DDS logged go to standard error as it
/// would have written them.
///
/// Returns Cyclone's first error (else warning, else return code) when it refuses.
pub fn create_domain(domain: u32, config: &str) -> Result<(), String> {
    let text = CString::new(config).map_err(|_| "the Cyclone DDS configuration holds a NUL character".to_string())?;
    // SAFETY: `capture` is a valid sink for the whole process life and uses no user data; Cyclone
    // copies the configuration before dds_create_domain returns; a null sink restores its default.
    let entity = unsafe {
        dds_set_log_sink(Some(capture), std::ptr::null_mut());
        let entity = dds_create_domain(domain, text.as_ptr());
        dds_set_log_sink(None, std::ptr::null_mut());
        entity
    };
    let logged = std::mem::take(&mut *LOGGED.lock().map_err(|_| "Cyclone DDS's log capture failed".to_string())?);
    if entity >= 0 {
        for (_, text) in logged {
            eprintln!("{text}");
        }
        return Ok(());
    }
    let first = |mask: u32| logged.iter().find(|(priority, _)| priority & mask != 0).map(|(_, text)| text.clone());
    let reason = first(FATAL | ERROR).or_else(|| first(WARNING)).unwrap_or_else(|| {
        // SAFETY: dds_strretcode returns a static string for any code
        unsafe { CStr::from_ptr(dds_strretcode(entity)) }.to_string_lossy().into_owned()
    });
    Err(format!("Cyclone DDS refused domain {domain}: {reason}"))
}
