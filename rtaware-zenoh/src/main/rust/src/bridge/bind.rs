//! Holding the bridge's sockets to one network interface (issue 38).
//!
//! Cyclone DDS binds its unicast receive sockets to 0.0.0.0 whatever its configuration says (its
//! interface setting chooses where it sends and what it advertises; `ddsi_udp_create_conn` binds
//! receive sockets to `INADDR_ANY`, cyclonedds issues 1923 and 2090), so on the loopback
//! interface it still listens on every address of the machine. This process therefore defines
//! `bind` itself: the executable's definition is the one every part of it links to (Cyclone DDS is
//! linked in statically), and once [`hold_to`] has been called it
//!
//! - binds an IPv4 socket asked for 0.0.0.0 to the interface's address instead, except
//! - a socket with `SO_REUSEADDR` (Cyclone's multicast receiver, which must stay on the wildcard
//!   address to receive its groups): it stays on 0.0.0.0 but is tied to the interface's packets
//!   with `SO_BINDTODEVICE` (Linux 5.7 and later allow that without privileges);
//! - refuses IPv6's `::` (`EADDRNOTAVAIL`): nothing of this process listens on every address.
//!
//! Every other bind (a given address, other families) goes to the kernel unchanged. Linux only:
//! elsewhere [`Binding::new`] refuses, so that DDS is never exposed silently.

use std::ffi::CString;
use std::net::Ipv4Addr;
use std::sync::OnceLock;

/// The interface every socket is held to.
pub struct Binding {
    /// Its name, for `SO_BINDTODEVICE`.
    #[cfg_attr(not(target_os = "linux"), allow(dead_code))]
    interface: CString,
    /// Its IPv4 address, for the sockets asked for 0.0.0.0.
    #[cfg_attr(not(target_os = "linux"), allow(dead_code))]
    address: Ipv4Addr,
}

impl Binding {
    /// The interface `interface` with address `address` (the parent looked it up).
    pub fn new(interface: &str, address: Ipv4Addr) -> Result<Binding, String> {
        if !cfg!(target_os = "linux") {
            return Err("holding DDS to one network interface is implemented on Linux only; configure Cyclone \
                        DDS yourself with CYCLONEDDS_URI"
                .to_string());
        }
        let interface = CString::new(interface).map_err(|_| format!("malformed interface name '{interface}'"))?;
        Ok(Binding { interface, address })
    }
}

static HELD: OnceLock<Binding> = OnceLock::new();

/// From now on every socket of this process is held to `binding`. Called once, before any
/// thread or socket exists.
pub fn hold_to(binding: Binding) {
    if HELD.set(binding).is_err() {
        panic!("the bridge's sockets are held to an interface once");
    }
}

#[cfg(target_os = "linux")]
mod linux {
    use super::HELD;
    use libc::{c_int, c_void, in6_addr, sockaddr, sockaddr_in, sockaddr_in6, socklen_t};
    use std::mem::size_of;

    /// `bind(2)` for this whole process: see the module's documentation.
    ///
    /// # Safety
    ///
    /// As `bind(2)`: `address` points to `length` readable bytes.
    #[unsafe(no_mangle)]
    pub unsafe extern "C" fn bind(fd: c_int, address: *const sockaddr, length: socklen_t) -> c_int {
        let Some(held) = HELD.get() else {
            // SAFETY: the caller's arguments, unchanged
            return unsafe { kernel_bind(fd, address, length) };
        };
        if address.is_null() {
            // SAFETY: as above; the kernel answers EFAULT
            return unsafe { kernel_bind(fd, address, length) };
        }
        // SAFETY: every sockaddr starts with its family; the caller gave `length` bytes
        let family = c_int::from(unsafe { (*address).sa_family });
        let length_bytes = length as usize;
        if family == libc::AF_INET && length_bytes >= size_of::<sockaddr_in>() {
            // SAFETY: an AF_INET address of at least sockaddr_in's size
            let mut v4 = unsafe { std::ptr::read_unaligned(address.cast::<sockaddr_in>()) };
            if v4.sin_addr.s_addr == libc::INADDR_ANY {
                if reuses_address(fd) {
                    // SAFETY: a NUL-terminated name and its length
                    let tied = unsafe {
                        libc::setsockopt(fd, libc::SOL_SOCKET, libc::SO_BINDTODEVICE,
                                         held.interface.as_ptr().cast::<c_void>(),
                                         held.interface.as_bytes_with_nul().len() as socklen_t)
                    };
                    if tied != 0 {
                        return -1; // errno from setsockopt
                    }
                } else {
                    v4.sin_addr.s_addr = u32::from(held.address).to_be();
                }
                // SAFETY: a complete sockaddr_in on our stack
                return unsafe {
                    kernel_bind(fd, (&raw const v4).cast::<sockaddr>(), size_of::<sockaddr_in>() as socklen_t)
                };
            }
        } else if family == libc::AF_INET6 && length_bytes >= size_of::<sockaddr_in6>() {
            // SAFETY: an AF_INET6 address of at least sockaddr_in6's size
            let v6 = unsafe { std::ptr::read_unaligned(address.cast::<sockaddr_in6>()) };
            if v6.sin6_addr.s6_addr == (in6_addr { s6_addr: [0; 16] }).s6_addr {
                // SAFETY: errno is this thread's
                unsafe { *libc::__errno_location() = libc::EADDRNOTAVAIL };
                return -1;
            }
        }
        // SAFETY: the caller's arguments, unchanged
        unsafe { kernel_bind(fd, address, length) }
    }

    /// Whether `SO_REUSEADDR` is set on `fd`.
    fn reuses_address(fd: c_int) -> bool {
        let mut value: c_int = 0;
        let mut size = size_of::<c_int>() as socklen_t;
        // SAFETY: an int and its size on our stack
        let status = unsafe {
            libc::getsockopt(fd, libc::SOL_SOCKET, libc::SO_REUSEADDR, (&raw mut value).cast::<c_void>(), &raw mut size)
        };
        status == 0 && value != 0
    }

    /// The system call itself (libc's `bind` is the one this module replaces).
    unsafe fn kernel_bind(fd: c_int, address: *const sockaddr, length: socklen_t) -> c_int {
        // SAFETY: the caller's promise, passed on
        unsafe { libc::syscall(libc::SYS_bind, fd, address, length) as c_int }
    }
}
