//! Zenoh's error messages as users read them: Zenoh's errors print the Rust source file and line
//! they were raised at (`... at /home/u/.cargo/registry/src/.../session.rs:123.`), which says
//! nothing to a robot's user and leaks the build machine's paths. They are cut out here.

/// `message` without the ` at <file>.rs:<line>.` locations Zenoh's errors append.
pub fn without_source_locations(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(at) = rest.find(" at ") {
        let after = &rest[at + 4..];
        match source_location_length(after) {
            Some(length) => {
                out.push_str(&rest[..at]);
                rest = &after[length..];
            }
            None => {
                out.push_str(&rest[..at + 4]);
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

/// The length of `<path>.rs:<line>` (and a following '.') at the start of `text`, if it is one.
fn source_location_length(text: &str) -> Option<usize> {
    let path_end = text.find(|c: char| c.is_whitespace()).unwrap_or(text.len());
    let token = &text[..path_end];
    let colon = token.find(".rs:")? + 3;
    let digits = token[colon + 1..].bytes().take_while(u8::is_ascii_digit).count();
    if digits == 0 {
        return None;
    }
    let mut end = colon + 1 + digits;
    if token[end..].starts_with('.') {
        end += 1;
    }
    Some(end)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zenoh_source_locations_are_cut_out() {
        let raw = "Unable to connect to any of [tcp/127.0.0.1:7447]!  at \
                   /home/u/.cargo/registry/src/index.crates.io-1949cf8c6b5b557f/zenoh-1.10.2/src/net/runtime/orchestrator.rs:404. \
                   - Caused by Can not create a new TCP link bound to 127.0.0.1:7447 at \
                   C:\\Users\\u\\zenoh-link-tcp-1.10.2\\src\\unicast.rs:77.";
        assert_eq!(
            without_source_locations(raw),
            "Unable to connect to any of [tcp/127.0.0.1:7447]!  - Caused by Can not create a new TCP link bound to 127.0.0.1:7447"
        );
    }

    #[test]
    fn other_uses_of_at_are_kept() {
        let text = "invalid key expression 'a//b' at position 2: empty chunk at a.rs:x";
        assert_eq!(without_source_locations(text), text);
        assert_eq!(without_source_locations("look at me"), "look at me");
        assert_eq!(without_source_locations("ends with at "), "ends with at ");
    }

    #[test]
    fn the_rust_path_of_a_real_zenoh_error_is_gone() {
        let error = zenoh::key_expr::KeyExpr::try_from("a//b").unwrap_err().to_string();
        assert!(error.contains(".rs:"), "the premise: Zenoh prints its source location: {error}");
        let cleaned = without_source_locations(&error);
        assert!(!cleaned.contains(".rs:"), "{cleaned}");
        assert!(!cleaned.is_empty());
    }
}
