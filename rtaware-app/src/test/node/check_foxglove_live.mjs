// Watches a running rtaware through its Foxglove WebSocket server (run --foxglove) with Foxglove's
// own client, @foxglove/ws-protocol (over the ws package), as Foxglove connects to a ROS 2 robot:
// checks the Server Info and every advertised channel (cdr with a ros2msg schema), subscribes to
// every channel, decodes every message with @foxglove/rosmsg2-serialization from the advertised
// schema, checks the fields of /scan, /tf_static and the timing channels and that no channel goes
// back in log time (/tf: odometry's and the ground truth's transforms), and when the server
// closes the connection (the run is over), or once it has MIN_SCANS scans if given (a simulator,
// which runs until stopped), prints one line "counts: {JSON}" and exits 0.
// Exits 1 on the first failure (a line "FAIL: ...").
//
// usage: RTAWARE_NPM_PEERS=DIR node check_foxglove_live.mjs ws://127.0.0.1:PORT [MIN_SCANS]
// DIR holds the node_modules of .ci/npm-peers.json (.ci/run installs them).
import { createRequire } from "node:module";

const url = process.argv[2];
const minScans = process.argv[3] === undefined ? 0 : Number(process.argv[3]);
const require = createRequire(process.env.RTAWARE_NPM_PEERS + "/package.json");
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const WebSocket = require("ws");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader } = require("@foxglove/rosmsg2-serialization");

function fail(message) {
  console.log("FAIL: " + message);
  process.exit(1);
}

const OUTCOMES = new Set(["ok", "miss", "skipped", "stale", "error"]);
const EPOCH_2020_NS = 1_577_836_800_000_000_000n;
const subscriptions = new Map(); // subscription id -> { topic, schemaName, reader, last }
const counts = {};
let serverInfo = null;
let channelCount = 0;
let total = 0;

const deadline = setTimeout(() => fail("the server did not close the connection within 300 s"), 300_000);
const client = new FoxgloveClient({ ws: new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });

client.on("error", (error) => fail(`client error: ${error}`));
client.on("serverInfo", (info) => {
  serverInfo = info;
  if (!info.name.startsWith("rtaware")) fail(`server name '${info.name}'`);
});
client.on("status", (status) => fail(`status from the server: ${JSON.stringify(status)}`));
client.on("advertise", (channels) => {
  if (serverInfo === null) fail("advertise before serverInfo");
  for (const channel of channels) {
    if (channel.encoding !== "cdr" || channel.schemaEncoding !== "ros2msg") {
      fail(`${channel.topic}: ${channel.encoding} with a ${channel.schemaEncoding} schema`);
    }
    let reader;
    try {
      reader = new MessageReader(parse(channel.schema, { ros2: true }));
    } catch (error) {
      fail(`${channel.topic}: schema ${channel.schemaName} does not parse: ${error}`);
    }
    channelCount++;
    counts[channel.topic] = 0;
    const id = client.subscribe(channel.id);
    subscriptions.set(id, { topic: channel.topic, schemaName: channel.schemaName, reader, last: -1n });
  }
});
client.on("message", ({ subscriptionId, timestamp, data }) => {
  const sub = subscriptions.get(subscriptionId);
  if (sub === undefined) fail(`a message for subscription ${subscriptionId}, which was never made`);
  let message;
  try {
    message = sub.reader.readMessage(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
  } catch (error) {
    fail(`${sub.topic}: ${sub.schemaName} does not decode: ${error}`);
  }
  if (timestamp < EPOCH_2020_NS) fail(`${sub.topic}: timestamp ${timestamp} is not Unix-epoch ns`);
  check(sub, timestamp, message);
  counts[sub.topic]++;
  total++;
  if (minScans > 0 && counts["/scan"] >= minScans) done();
});
client.on("close", done);

function done() {
  clearTimeout(deadline);
  if (serverInfo === null) fail("the connection closed before the Server Info");
  console.log("counts: " + JSON.stringify({ server: serverInfo.name, channels: channelCount, total, topics: counts }));
  process.exit(0);
}

function check(sub, timestamp, message) {
  // Every channel in log-time order (/tf carries odometry's and the ground truth's transforms).
  if (timestamp < sub.last) fail(`${sub.topic}: log time goes back: ${timestamp} after ${sub.last}`);
  sub.last = timestamp;
  if (sub.topic === "/scan") {
    if (message.header.frame_id !== "laser") fail(`/scan frame '${message.header.frame_id}'`);
    if (!(message.ranges.length > 0) || !(message.angle_increment > 0) || !(message.range_max > 0)) {
      fail(`/scan without beams: ${message.ranges.length} ranges, increment ${message.angle_increment}`);
    }
  } else if (sub.topic.startsWith("/rtaware/timing/")) {
    if (!OUTCOMES.has(message.outcome)) fail(`${sub.topic}: outcome '${message.outcome}'`);
    if (message.end_ns < message.start_ns) {
      fail(`${sub.topic}: ends before it starts: ${message.start_ns} .. ${message.end_ns}`);
    }
    if (!(message.exec >= 0) || !(message.lateness >= 0)) {
      fail(`${sub.topic}: exec ${message.exec} ms, lateness ${message.lateness} ms`);
    }
  } else if (sub.topic === "/tf_static") {
    const children = message.transforms.map((t) => t.child_frame_id);
    if (!children.includes("laser")) fail(`/tf_static without base_link -> laser: ${children}`);
  }
}
