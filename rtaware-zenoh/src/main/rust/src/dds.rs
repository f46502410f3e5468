//! The ROS 2 DDS bridge (issue 29): ZettaScale's `zenoh-plugin-ros2dds`, built on Eclipse Cyclone
//! DDS, started in a Zenoh runtime of its own inside this process. The runtime listens on one
//! loopback endpoint; rtaware's sessions connect to it like to any Zenoh peer and announce their
//! publishers and subscriptions the way one bridge announces routes to another, so that the plugin
//! creates the matching DDS writers and readers (`rt/<topic>`) on the DDS domain.
//!
//! Every decision (the plugin's settings, the Cyclone DDS configuration, the distribution) is
//! taken on the Java side and arrives here as text. Without the `dds` cargo feature the functions
//! exist and fail with a message saying how to build them.

#[cfg(feature = "dds")]
mod enabled {
    use zenoh::internal::plugins::PluginsManager;
    use zenoh::internal::runtime::{Runtime, RuntimeBuilder};
    use zenoh::Config;
    use zenoh_runtime::ZRuntime;

    /// A running bridge: the runtime the plugin was started in. The plugin's DDS participant lives
    /// as long as the process (the plugin has no stop); closing the runtime ends its Zenoh side.
    pub struct DdsBridge {
        runtime: Runtime,
    }

    /// Sets the environment the plugin and Cyclone DDS read when they start (`ROS_DISTRO`,
    /// `CYCLONEDDS_URI`; an empty value removes the variable), then starts a peer runtime listening
    /// on `listen` with the plugin configured by `plugin_config` (JSON5, the `plugins/ros2dds`
    /// section of a bridge's configuration). Returns the bridge and the endpoints it listens on.
    pub fn start(listen: &str, plugin_config: &str, env: &[(String, String)]) -> Result<(DdsBridge, Vec<String>), String> {
        for (name, value) in env {
            // Read by the plugin (ROS_DISTRO, once per process) and by Cyclone DDS when the plugin
            // creates its participant, both after this point; nothing in this library reads them.
            if value.is_empty() {
                std::env::remove_var(name);
            } else {
                std::env::set_var(name, value);
            }
        }
        let mut config = Config::default();
        let mut set = |key: &str, value: String| {
            config.insert_json5(key, &value).map_err(|e| format!("DDS bridge configuration {key}={value}: {e}"))
        };
        set("mode", "\"peer\"".to_string())?;
        set("listen/endpoints", format!("[{:?}]", listen))?;
        set("connect/endpoints", "[]".to_string())?;
        set("scouting/multicast/enabled", "false".to_string())?;
        // the plugin's publication caches of transient-local topics need timestamps
        set("timestamping/enabled", "true".to_string())?;
        set("plugins/ros2dds", plugin_config.to_string())?;
        let mut plugins = PluginsManager::static_plugins_only();
        plugins.declare_static_plugin::<zenoh_plugin_ros2dds::ROS2Plugin, &str>("ros2dds", true);
        let runtime = ZRuntime::Application.block_in_place(async move {
            let mut runtime = RuntimeBuilder::new(config).plugins_manager(plugins).build().await?;
            runtime.start().await?;
            Ok::<Runtime, zenoh::Error>(runtime)
        });
        let runtime = runtime.map_err(|e| format!("cannot start the ROS 2 DDS bridge: {e}"))?;
        let endpoints = runtime.get_locators().iter().map(|l| l.to_string()).collect();
        Ok((DdsBridge { runtime }, endpoints))
    }

    impl DdsBridge {
        /// The runtime's Zenoh id as Zenoh prints it.
        pub fn zid(&self) -> String {
            self.runtime.zid().to_string()
        }

        /// Closes the runtime: the plugin's routes lose their Zenoh side.
        pub fn close(&self) -> Result<(), String> {
            use zenoh::Wait;
            self.runtime.close().wait().map_err(|e| format!("closing the ROS 2 DDS bridge: {e}"))
        }
    }

    /// Whether this library was built with the bridge.
    pub const AVAILABLE: bool = true;
}

#[cfg(not(feature = "dds"))]
mod enabled {
    const MISSING: &str = "this native Zenoh layer was built without the ROS 2 DDS bridge (cargo feature \
                           'dds', which needs libclang and cmake to build Eclipse Cyclone DDS)";

    /// Stands for the bridge in a library built without it; never constructed.
    pub struct DdsBridge;

    /// Always fails: the bridge is not in this build.
    pub fn start(_listen: &str, _plugin_config: &str, _env: &[(String, String)]) -> Result<(DdsBridge, Vec<String>), String> {
        Err(MISSING.to_string())
    }

    impl DdsBridge {
        pub fn zid(&self) -> String {
            String::new()
        }

        pub fn close(&self) -> Result<(), String> {
            Ok(())
        }
    }

    /// Whether this library was built with the bridge.
    pub const AVAILABLE: bool = false;
}

pub use enabled::{start, DdsBridge, AVAILABLE};
