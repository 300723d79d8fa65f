/* A ROS 2 user's view of dem_server, built from the message files of
 * ros2/dem_interfaces alone: their DDS IDL written as rosidl does
 * (msg_to_dds_idl.py), compiled by idlc, and read and written with libddsc
 * the way rmw_cyclonedds_cpp does (topic rt/dem/<server>/..., type
 * dem_interfaces::msg::dds_::<Type>_, plain CDR; each endpoint declaring
 * its type's hash in USER_DATA, "typehash=RIHS01_...;", as ROS 2 does since
 * Iron, from the message files: typehashes.h). None of the project's
 * headers is used.
 *
 *   rosidl_interop DOMAIN SERVER TELEMETRY_CYCLES
 *
 * With a server on DOMAIN that has a 2D case loaded and publishes telemetry
 * every TELEMETRY_CYCLES cycles, it checks that
 *   - the durable status arrives at once, from a transient-local reader;
 *   - a get_state command built from Command.msg gets its Reply;
 *   - a cycle command runs, and the plate forces published meanwhile all
 *     reach a reader of the documented depth (docs/ROS2.md: keep last
 *     1024), in order and exactly (the last equals get_state's afterwards),
 *     while a reader of ROS 2's default depth of 10 that does not take them
 *     in time keeps only the last 10.
 * Prints what it saw; exits 0 when every check holds, 1 otherwise. */
#include <dds/dds.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dem_interfaces/msg/dds_/Command_.h"
#include "dem_interfaces/msg/dds_/PlateForces_.h"
#include "dem_interfaces/msg/dds_/Reply_.h"
#include "dem_interfaces/msg/dds_/Status_.h"
#include "typehashes.h"

#define CLIENT_ID "rosidl_interop"
#define CYCLES 200

static int failures = 0;

static void check(int condition, const char *what) {
  printf("%s: %s\n", condition ? "ok" : "FAILED", what);
  if (!condition) ++failures;
}

static dds_entity_t must(dds_entity_t entity, const char *what) {
  if (entity < 0) {
    fprintf(stderr, "%s: %s\n", what, dds_strretcode(entity));
    exit(1);
  }
  return entity;
}

static dds_entity_t topic(dds_entity_t participant, const dds_topic_descriptor_t *type, const char *server,
                          const char *name) {
  char full[256];
  snprintf(full, sizeof full, "rt/dem/%s/%s", server, name);
  return must(dds_create_topic(participant, type, full, NULL, NULL), full);
}

static dds_qos_t *qos(int transient_local, int depth) {
  dds_qos_t *q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(q, transient_local ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, depth);
  return q;
}

/* The QoS of an endpoint of a type with this hash: rmw_cyclonedds_cpp's USER_DATA. */
static dds_qos_t *declaring(const dds_qos_t *base, const char *type_hash) {
  char data[128];
  snprintf(data, sizeof data, "typehash=%s;", type_hash);
  dds_qos_t *q = dds_create_qos();
  dds_copy_qos(q, base);
  dds_qset_userdata(q, data, strlen(data));
  return q;
}

/* Waits until the reader has a sample that `accept` takes (accept copies
 * what it needs: the sample goes back to the reader after the call). */
static int wait_for(dds_entity_t reader, int (*accept)(const void *, uint64_t), uint64_t request,
                    dds_duration_t timeout) {
  const dds_time_t deadline = dds_time() + timeout;
  while (dds_time() < deadline) {
    void *samples[1] = {NULL};
    dds_sample_info_t info;
    const dds_return_t n = dds_take(reader, samples, &info, 1, 1);
    if (n > 0) {
      const int taken = info.valid_data && accept(samples[0], request);
      dds_return_loan(reader, samples, n);
      if (taken) return 1;
    } else {
      dds_sleepfor(DDS_MSECS(5));
    }
  }
  return 0;
}

static int is_loaded_status(const void *sample, uint64_t unused) {
  (void)unused;
  return ((const dem_interfaces_msg_dds__Status_ *)sample)->state_ == 1; /* Status.LOADED */
}

/* The reply's scalars, copied while the sample is on loan. */
typedef struct {
  int found;
  int32_t status;
  uint8_t kind;
  uint64_t cycles_run;
  uint64_t cycle;
  uint32_t walls;
  double last_stress[16];
  char message[256];
  char server[64];
} ReplySeen;
static ReplySeen reply_seen;

static int is_our_reply(const void *sample, uint64_t request) {
  const dem_interfaces_msg_dds__Reply_ *r = sample;
  if (strcmp(r->client_id_, CLIENT_ID) != 0 || r->request_id_ != request || !r->last_) return 0;
  reply_seen.found = 1;
  reply_seen.status = r->status_;
  reply_seen.kind = r->kind_;
  reply_seen.cycles_run = r->cycles_run_;
  reply_seen.cycle = r->state_.cycle_;
  reply_seen.walls = r->plates_.walls_._length;
  for (uint32_t i = 0; i < r->plates_.walls_._length && i < 16; ++i) {
    reply_seen.last_stress[i] = r->plates_.walls_._buffer[i].normal_stress_;
  }
  snprintf(reply_seen.message, sizeof reply_seen.message, "%s", r->message_);
  snprintf(reply_seen.server, sizeof reply_seen.server, "%s", r->server_);
  return 1;
}

static dem_interfaces_msg_dds__Command_ command(const char *server, uint64_t request, uint8_t kind) {
  dem_interfaces_msg_dds__Command_ c;
  memset(&c, 0, sizeof c);
  char *empty = "";
  c.server_ = (char *)server;
  c.client_id_ = CLIENT_ID;
  c.request_id_ = request;
  c.kind_ = kind;
  c.load_case_.path_ = c.load_case_.text_ = c.load_case_.source_name_ = empty;
  c.wall_velocity_.wall_ = c.wall_servo_.wall_ = c.run_until_.wall_ = c.query_.wall_ = empty;
  c.snapshot_.path_ = c.parameter_.name_ = c.parameter_.material_ = empty;
  return c;
}

static void send_and_await(dds_entity_t writer, dds_entity_t reply_reader, dem_interfaces_msg_dds__Command_ *c) {
  memset(&reply_seen, 0, sizeof reply_seen);
  const dds_return_t rc = dds_write(writer, c);
  if (rc != DDS_RETCODE_OK) {
    fprintf(stderr, "writing the command: %s\n", dds_strretcode(rc));
    exit(1);
  }
  wait_for(reply_reader, is_our_reply, c->request_id_, DDS_SECS(20));
}

static uint32_t matched(dds_entity_t entity, int writer) {
  if (writer) {
    dds_publication_matched_status_t s;
    dds_get_publication_matched_status(entity, &s);
    return s.current_count;
  }
  dds_subscription_matched_status_t s;
  dds_get_subscription_matched_status(entity, &s);
  return s.current_count;
}

/* Takes every plate forces sample a reader holds: their cycles, and the
 * walls' stresses of the last one. */
static int take_all(dds_entity_t reader, uint64_t *cycles, int max, double *last_stress, uint32_t *last_walls) {
  int count = 0;
  for (;;) {
    void *samples[64] = {NULL};
    dds_sample_info_t infos[64];
    const dds_return_t n = dds_take(reader, samples, infos, 64, 64);
    if (n <= 0) break;
    for (int i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const dem_interfaces_msg_dds__PlateForces_ *p = samples[i];
      if (count < max) cycles[count] = p->cycle_;
      ++count;
      *last_walls = p->walls_._length;
      for (uint32_t w = 0; w < p->walls_._length && w < 16; ++w) last_stress[w] = p->walls_._buffer[w].normal_stress_;
    }
    dds_return_loan(reader, samples, n);
  }
  return count;
}

int main(int argc, char **argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: rosidl_interop DOMAIN SERVER TELEMETRY_CYCLES\n");
    return 2;
  }
  setvbuf(stdout, NULL, _IOLBF, 0); /* each line as it is printed, also into a pipe */
  const dds_domainid_t domain = (dds_domainid_t)atoi(argv[1]);
  const char *server = argv[2];
  const uint64_t telemetry_cycles = strtoull(argv[3], NULL, 10);

  const dds_entity_t participant = must(dds_create_participant(domain, NULL, NULL), "creating the participant");
  const dds_entity_t status_topic = topic(participant, &dem_interfaces_msg_dds__Status__desc, server, "status");
  const dds_entity_t plates_topic = topic(participant, &dem_interfaces_msg_dds__PlateForces__desc, server, "plate_forces");
  const dds_entity_t command_topic = topic(participant, &dem_interfaces_msg_dds__Command__desc, server, "command");
  const dds_entity_t reply_topic = topic(participant, &dem_interfaces_msg_dds__Reply__desc, server, "reply");

  dds_qos_t *base_durable = qos(1, 1), *base_documented = qos(0, 1024), *base_default = qos(0, 10);
  dds_qos_t *durable = declaring(base_durable, TYPEHASH_dem_interfaces_Status);
  dds_qos_t *documented = declaring(base_documented, TYPEHASH_dem_interfaces_PlateForces);
  dds_qos_t *plates_default = declaring(base_default, TYPEHASH_dem_interfaces_PlateForces);
  dds_qos_t *command_default = declaring(base_default, TYPEHASH_dem_interfaces_Command);
  dds_qos_t *reply_default = declaring(base_default, TYPEHASH_dem_interfaces_Reply);
  const dds_entity_t status_reader = must(dds_create_reader(participant, status_topic, durable, NULL), "status reader");
  const dds_entity_t plates_reader = must(dds_create_reader(participant, plates_topic, documented, NULL), "plates reader");
  const dds_entity_t shallow_reader =
      must(dds_create_reader(participant, plates_topic, plates_default, NULL), "depth-10 reader");
  const dds_entity_t command_writer =
      must(dds_create_writer(participant, command_topic, command_default, NULL), "command writer");
  const dds_entity_t reply_reader = must(dds_create_reader(participant, reply_topic, reply_default, NULL), "reply reader");

  check(wait_for(status_reader, is_loaded_status, 0, DDS_SECS(20)),
        "the durable status arrived, state LOADED");

  /* The server's command reader and reply writer: matched before the first command. */
  const dds_time_t deadline = dds_time() + DDS_SECS(20);
  while ((matched(command_writer, 1) == 0 || matched(reply_reader, 0) == 0 || matched(plates_reader, 0) == 0) &&
         dds_time() < deadline) {
    dds_sleepfor(DDS_MSECS(10));
  }
  check(matched(command_writer, 1) > 0 && matched(reply_reader, 0) > 0, "matched the server's command and reply endpoints");

  dem_interfaces_msg_dds__Command_ get_state = command(server, 1, 7); /* Command.GET_STATE */
  send_and_await(command_writer, reply_reader, &get_state);
  check(reply_seen.found, "a reply to get_state arrived");
  check(reply_seen.status == 0 && reply_seen.kind == 7 && strcmp(reply_seen.server, server) == 0,
        "get_state: status OK (0), kind GET_STATE (7), from the server");
  const uint64_t start = reply_seen.cycle;
  printf("get_state: cycle %" PRIu64 ", %u walls: %s\n", start, reply_seen.walls, reply_seen.message);

  dem_interfaces_msg_dds__Command_ cycle = command(server, 2, 4); /* Command.CYCLE */
  cycle.cycle_.cycles_ = CYCLES;
  send_and_await(command_writer, reply_reader, &cycle);
  check(reply_seen.found && reply_seen.status == 0 && reply_seen.cycles_run == CYCLES, "cycle 200: done, 200 cycles run");
  dds_sleepfor(DDS_MSECS(500)); /* the last telemetry sample follows the reply */

  dem_interfaces_msg_dds__Command_ after = command(server, 3, 7);
  send_and_await(command_writer, reply_reader, &after);
  check(reply_seen.found && reply_seen.cycle == start + CYCLES, "get_state after the run: at the cycle it ended");

  uint64_t cycles[4096];
  double last_stress[16] = {0};
  uint32_t last_walls = 0;
  const int expected = (int)(CYCLES / telemetry_cycles);
  const int all = take_all(plates_reader, cycles, 4096, last_stress, &last_walls);
  int in_order = 1;
  int from = 0;
  while (from < all && cycles[from] <= start) ++from; /* samples from before the command */
  for (int i = from; i < all; ++i) in_order &= cycles[i] == start + (uint64_t)(i - from + 1) * telemetry_cycles;
  printf("depth 1024: %d samples of this run (cycles %" PRIu64 " to %" PRIu64 ")\n", all - from,
         all > from ? cycles[from] : 0, all > 0 ? cycles[all - 1] : 0);
  check(all - from == expected && in_order, "every plate forces sample of the run, in order, reached the depth-1024 reader");
  int exact = last_walls == reply_seen.walls && last_walls > 0;
  for (uint32_t w = 0; w < last_walls && w < 16; ++w) exact &= last_stress[w] == reply_seen.last_stress[w];
  check(exact, "the last sample's wall stresses equal get_state's, bit for bit");

  uint64_t shallow_cycles[64];
  double ignored[16];
  uint32_t ignored_walls = 0;
  const int kept = take_all(shallow_reader, shallow_cycles, 64, ignored, &ignored_walls);
  printf("depth 10, not taken in time: %d samples kept of %d\n", kept, expected);
  check(kept == 10 && shallow_cycles[kept - 1] == start + CYCLES, "the depth-10 reader kept only the last 10");

  /* Shut the server down, so the test ends with it. */
  dem_interfaces_msg_dds__Command_ shutdown = command(server, 4, 8); /* Command.SHUTDOWN */
  send_and_await(command_writer, reply_reader, &shutdown);
  check(reply_seen.found && reply_seen.status == 0, "shutdown: accepted");

  dds_qos_t *qoses[] = {base_durable, base_documented, base_default, durable, documented, plates_default,
                      command_default, reply_default};
  for (size_t i = 0; i < sizeof qoses / sizeof qoses[0]; ++i) dds_delete_qos(qoses[i]);
  dds_delete(participant);
  printf("%s\n", failures == 0 ? "all checks hold" : "some checks FAILED");
  return failures == 0 ? 0 : 1;
}
