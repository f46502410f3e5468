//! `rtaware-dds-bridge`: ZettaScale's ROS 2 DDS bridge (`zenoh-plugin-ros2dds`, on Eclipse Cyclone
//! DDS) in a process of its own, started and owned by `io.rtaware.zenoh.DdsBridge` (issue 29).
//!
//! It runs in its own process, as `zenoh-bridge-ros2dds` does, for three reasons (issue 38): the
//! plugin reads `ROS_DISTRO` from the environment and writes `CYCLONEDDS_URI` into it while other
//! threads run, which inside a JVM is undefined behaviour, so the environment here is set by the
//! parent before this process starts and this code never writes it; Cyclone DDS binds its receive
//! sockets on every address and has no setting against it ([`bind`] holds them to the interface);
//! and the plugin has no stop, so its DDS participant ends only with its process.
//!
//! Every decision is taken by the Java side and arrives as arguments:
//!
//! ```text
//! rtaware-dds-bridge --listen tcp/127.0.0.1:0 --plugin-config JSON5 --cyclone-config CONFIG
//!                    [--bind-interface NAME --bind-address IPV4]
//! ```
//!
//! It creates the Cyclone DDS domain itself with `CONFIG` (what `CYCLONEDDS_URI` may hold: XML
//! fragments and file names) before the plugin starts, so that a configuration Cyclone DDS refuses
//! ends the process at once with Cyclone's reason, and the plugin's own participant joins that
//! domain (Cyclone DDS reads no environment for a domain that exists). Then it prints one line on
//! standard output, `ready <zid> <endpoint>...` or `error <reason>` (exit status 2), and runs until
//! its standard input ends (the parent closed it, or died).

mod bind;
mod cyclone;

use std::io::{Read, Write};
use std::net::Ipv4Addr;
use std::process::ExitCode;

use zenoh::Config;
use zenoh::Wait;
use zenoh::internal::plugins::PluginsManager;
use zenoh::internal::runtime::{Runtime, RuntimeBuilder};
use zenoh_runtime::ZRuntime;

/// What the parent asks for.
struct Arguments {
    listen: String,
    plugin_config: String,
    cyclone_config: String,
    bind: Option<bind::Binding>,
}

fn main() -> ExitCode {
    // One line for a panic anywhere (the plugin's tasks included), never a backtrace.
    std::panic::set_hook(Box::new(|info| {
        let message = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_string());
        eprintln!("rtaware-dds-bridge: panic: {}", message.lines().next().unwrap_or(""));
    }));
    let runtime = match arguments(std::env::args().skip(1)).and_then(start) {
        Ok(runtime) => runtime,
        Err(reason) => {
            say(&format!("error {}", reason.replace('\n', " ")));
            return ExitCode::from(2);
        }
    };
    // Until the parent closes our standard input (or dies, which closes it too).
    let _ = std::io::stdin().lock().read_to_end(&mut Vec::new());
    match runtime.close().wait() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("rtaware-dds-bridge: closing: {e}");
            ExitCode::FAILURE
        }
    }
}

fn say(line: &str) {
    let mut out = std::io::stdout().lock();
    let _ = writeln!(out, "{line}");
    let _ = out.flush();
}

fn arguments(args: impl Iterator<Item = String>) -> Result<Arguments, String> {
    let (mut listen, mut plugin_config, mut cyclone_config, mut interface, mut address) = (None, None, None, None, None);
    let mut args = args;
    while let Some(name) = args.next() {
        let value = args.next().ok_or_else(|| format!("{name} needs a value"))?;
        let slot = match name.as_str() {
            "--listen" => &mut listen,
            "--plugin-config" => &mut plugin_config,
            "--cyclone-config" => &mut cyclone_config,
            "--bind-interface" => &mut interface,
            "--bind-address" => &mut address,
            _ => return Err(format!("unknown argument '{name}'")),
        };
        *slot = Some(value);
    }
    let bind = match (interface, address) {
        (None, None) => None,
        (Some(interface), Some(address)) => {
            let address: Ipv4Addr = address.parse().map_err(|_| format!("--bind-address: not an IPv4 address: '{address}'"))?;
            Some(bind::Binding::new(&interface, address)?)
        }
        _ => return Err("--bind-interface and --bind-address go together".to_string()),
    };
    Ok(Arguments {
        listen: listen.ok_or("--listen is missing")?,
        plugin_config: plugin_config.ok_or("--plugin-config is missing")?,
        cyclone_config: cyclone_config.ok_or("--cyclone-config is missing")?,
        bind,
    })
}

/// Creates the DDS domain, then starts the runtime with the plugin and says `ready`.
fn start(arguments: Arguments) -> Result<Runtime, String> {
    if let Some(binding) = arguments.bind {
        // Before any socket exists: from here on, a socket bound to every address is bound to
        // the interface instead.
        bind::hold_to(binding);
    }
    let mut config = Config::default();
    let mut set = |key: &str, value: String| {
        config.insert_json5(key, &value).map_err(|e| format!("DDS bridge configuration {key}={value}: {e}"))
    };
    set("mode", "\"peer\"".to_string())?;
    set("listen/endpoints", format!("[{:?}]", arguments.listen))?;
    set("connect/endpoints", "[]".to_string())?;
    set("scouting/multicast/enabled", "false".to_string())?;
    // the plugin's publication caches of transient-local topics need timestamps
    set("timestamping/enabled", "true".to_string())?;
    set("plugins/ros2dds", arguments.plugin_config)?;
    let domain = config
        .get_json("plugins/ros2dds/domain")
        .map_err(|_| "the plugin configuration names no domain".to_string())?;
    let domain: u32 = domain.trim().parse().map_err(|_| format!("the plugin configuration's domain is not a number: {domain}"))?;
    cyclone::create_domain(domain, &arguments.cyclone_config)?;

    let mut plugins = PluginsManager::static_plugins_only();
    plugins.declare_static_plugin::<zenoh_plugin_ros2dds::ROS2Plugin, &str>("ros2dds", true);
    let runtime = ZRuntime::Application
        .block_in_place(async move {
            let mut runtime = RuntimeBuilder::new(config).plugins_manager(plugins).build().await?;
            runtime.start().await?;
            Ok::<Runtime, zenoh::Error>(runtime)
        })
        .map_err(|e| format!("cannot start the bridge's Zenoh runtime: {e}"))?;
    let endpoints: Vec<String> = runtime.get_locators().iter().map(|l| l.to_string()).collect();
    say(&format!("ready {} {}", runtime.zid(), endpoints.join(" ")));
    Ok(runtime)
}

#[cfg(test)]
mod tests {
    use super::arguments;

    fn args(list: &[&str]) -> impl Iterator<Item = String> {
        list.iter().map(|s| s.to_string()).collect::<Vec<_>>().into_iter()
    }

    #[test]
    fn arguments_name_what_is_wrong() {
        let base = ["--listen", "tcp/127.0.0.1:0", "--plugin-config", "{}", "--cyclone-config", ""];
        assert!(arguments(args(&base)).unwrap().bind.is_none());
        assert_eq!(arguments(args(&["--listen"])).err().unwrap(), "--listen needs a value");
        assert_eq!(arguments(args(&["--port", "1"])).err().unwrap(), "unknown argument '--port'");
        assert_eq!(arguments(args(&base[..4])).err().unwrap(), "--cyclone-config is missing");
        let mut half = base.to_vec();
        half.extend(["--bind-interface", "lo"]);
        assert_eq!(arguments(args(&half)).err().unwrap(), "--bind-interface and --bind-address go together");
        half.extend(["--bind-address", "localhost"]);
        assert_eq!(arguments(args(&half)).err().unwrap(), "--bind-address: not an IPv4 address: 'localhost'");
    }
}
