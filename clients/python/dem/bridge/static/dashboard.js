// The dashboard: connects back to the bridge that served it with the
// Foxglove WebSocket protocol (foxglove.websocket.v1), subscribes to every
// channel it advertises, decodes the CDR messages by their ros2msg schemas
// (cdr.js) and shows, per server: its status, its contact statistics, and
// each loaded wall's normal stress against its settlement, one Chart.js
// curve per wall, growing as samples come. window.demDashboard holds what
// it has seen, for tests and the curious.
"use strict";

const dashboard = {
  connected: false,
  protocol: null,
  messages: 0,
  servers: {},  // name -> {status, stats, walls: {wall: [{x: settlement m, y: stress kPa}]}, chart, element}
  points(server, wall) {
    const s = this.servers[server];
    return s && s.walls[wall] ? s.walls[wall].length : 0;
  },
};
window.demDashboard = dashboard;

const channels = new Map();  // channel id -> {topic, server, kind, decoder}
const COLOURS = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"];

function serverPanel(name) {
  if (dashboard.servers[name]) return dashboard.servers[name];
  document.getElementById("empty").style.display = "none";
  const element = document.createElement("div");
  element.className = "server";
  element.id = `server-${name}`;
  element.innerHTML = `<h2>${name}</h2><div class="status">waiting for its status</div>` +
    `<div class="stats"></div><div class="chart"><canvas></canvas></div>`;
  document.getElementById("servers").appendChild(element);
  const chart = new Chart(element.querySelector("canvas"), {
    type: "scatter",
    data: { datasets: [] },
    options: {
      animation: false,
      maintainAspectRatio: false,
      showLine: true,
      elements: { point: { radius: 1.5 }, line: { borderWidth: 1.5 } },
      scales: {
        x: { title: { display: true, text: "settlement (m)" } },
        y: { title: { display: true, text: "normal stress (kPa)" }, beginAtZero: true },
      },
      plugins: { title: { display: true, text: "stress against settlement of the loaded walls" } },
    },
  });
  const panel = { status: null, stats: null, walls: {}, chart, element, dirty: false };
  dashboard.servers[name] = panel;
  return panel;
}

function removeServer(name) {
  const panel = dashboard.servers[name];
  if (!panel) return;
  panel.element.querySelector(".status").textContent += " (gone)";
}

function onPlateForces(panel, message) {
  for (const wall of message.walls) {
    let points = panel.walls[wall.name];
    if (!points) {
      if (wall.normal_stress === 0 && wall.settlement === 0) continue;  // not loaded (yet)
      points = panel.walls[wall.name] = [];
      const colour = COLOURS[panel.chart.data.datasets.length % COLOURS.length];
      panel.chart.data.datasets.push({ label: wall.name, data: points, borderColor: colour, backgroundColor: colour });
    }
    const last = points[points.length - 1];
    if (last && last.cycle === message.cycle) continue;
    points.push({ x: wall.settlement, y: wall.normal_stress / 1000, cycle: Number(message.cycle) });
  }
  panel.dirty = true;
}

function onContactStats(panel, s) {
  panel.stats = s;
  panel.element.querySelector(".stats").textContent =
    `cycle ${s.cycle}: ${s.contacts} contacts (${(100 * s.sliding_fraction).toFixed(1)}% sliding), ` +
    `coordination ${s.coordination_number.toFixed(3)}, mean normal force ${s.mean_normal_force.toPrecision(4)} N, ` +
    `kinetic energy ${s.kinetic_energy.toPrecision(4)} J`;
}

function onStatus(panel, s) {
  panel.status = s;
  let text = `${s.state_name}`;
  if (s.case_name) text += ` - ${s.case_name} (${s.dimension}D, ${s.particles} particles), cycle ${s.cycle}, ` +
    `t = ${s.time.toPrecision(5)} s`;
  if (s.command) text += ` - ${s.command} ${(100 * s.progress).toFixed(0)}%`;
  if (s.message) text += ` - ${s.message}`;
  panel.element.querySelector(".status").textContent = text;
}

function connect() {
  const socket = new WebSocket(`ws://${location.host}/`, ["foxglove.websocket.v1"]);
  socket.binaryType = "arraybuffer";
  socket.onopen = () => {
    dashboard.connected = true;
    dashboard.protocol = socket.protocol;
    document.getElementById("connection").textContent = `connected to ${location.host} (${socket.protocol})`;
  };
  socket.onclose = () => {
    dashboard.connected = false;
    document.getElementById("connection").textContent = "disconnected; reconnecting...";
    setTimeout(connect, 1000);
  };
  socket.onmessage = (event) => {
    if (typeof event.data === "string") {
      const message = JSON.parse(event.data);
      if (message.op === "advertise") {
        const subscriptions = [];
        for (const c of message.channels) {
          const [, , server, kind] = c.topic.split("/");  // /dem/<server>/<kind>
          channels.set(c.id, { topic: c.topic, server, kind, decoder: new CdrDecoder(c.schemaName, c.schema) });
          serverPanel(server);
          subscriptions.push({ id: c.id, channelId: c.id });
        }
        socket.send(JSON.stringify({ op: "subscribe", subscriptions }));
      } else if (message.op === "unadvertise") {
        for (const id of message.channelIds) {
          const channel = channels.get(id);
          channels.delete(id);
          if (channel && channel.kind === "status") removeServer(channel.server);
        }
      }
      return;
    }
    const view = new DataView(event.data);
    if (view.getUint8(0) !== 0x01) return;  // only message data
    const channel = channels.get(view.getUint32(1, true));  // subscription ids are channel ids here
    if (!channel) return;
    const message = channel.decoder.decode(new Uint8Array(event.data, 13));
    dashboard.messages++;
    const panel = serverPanel(channel.server);
    if (channel.kind === "plate_forces") onPlateForces(panel, message);
    else if (channel.kind === "contact_stats") onContactStats(panel, message);
    else if (channel.kind === "status") onStatus(panel, message);
  };
}

// Charts redraw a few times a second, not at every sample.
setInterval(() => {
  for (const panel of Object.values(dashboard.servers)) {
    if (panel.dirty) {
      panel.chart.update("none");
      panel.dirty = false;
    }
  }
}, 250);

connect();
