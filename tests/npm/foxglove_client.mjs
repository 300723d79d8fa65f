// A Foxglove WebSocket client from the npm registry (@foxglove/ws-protocol,
// over the `ws` package) against a bridge: prints, as JSON, the protocol the
// server negotiated, the channels it advertised, and the first N messages
// of the channels whose topic ends with SUFFIX (base64 CDR), then exits.
// Says "subscribed to TOPIC" on stderr once it has subscribed.
// Exits 1 on an error or when N messages did not come within 60 s.
//   node foxglove_client.mjs WS_URL SUFFIX N
import foxglove from "@foxglove/ws-protocol";
import WebSocket from "ws";

const { FoxgloveClient } = foxglove;
const [url, suffix, wanted] = [process.argv[2], process.argv[3], Number(process.argv[4])];
const socket = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
const client = new FoxgloveClient({ ws: socket });
const channels = [];
const messages = [];
const subscribed = new Map();
let serverInfo = null;

const timer = setTimeout(() => {
  console.error(`only ${messages.length} of ${wanted} messages in 60 s`);
  process.exit(1);
}, 60000);

client.on("serverInfo", (info) => { serverInfo = info; });
client.on("advertise", (advertised) => {
  for (const channel of advertised) {
    channels.push(channel);
    if (channel.topic.endsWith(suffix)) {
      subscribed.set(client.subscribe(channel.id), channel);
      console.error(`subscribed to ${channel.topic}`);  // a test waits for this line before it runs the server
    }
  }
});
client.on("message", ({ subscriptionId, timestamp, data }) => {
  const channel = subscribed.get(subscriptionId);
  messages.push({
    topic: channel.topic, receiveTime: timestamp.toString(),
    data: Buffer.from(data.buffer, data.byteOffset, data.byteLength).toString("base64"),
  });
  if (messages.length === wanted) {
    clearTimeout(timer);
    console.log(JSON.stringify({ protocol: socket.protocol, serverInfo, channels, messages }));
    client.close();
  }
});
client.on("error", (error) => {
  console.error(`error: ${error?.message ?? error}`);
  process.exit(1);
});
