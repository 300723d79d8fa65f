/* A ROS 2 node built from the package's first message files
 * (dem_interfaces_0.1.0/msg, main at 0308f76: before Command gained `force`
 * and ContactQuery `particle_set` and `particle`, ContactEntry three fields),
 * declaring their type hashes as ROS 2 does since Iron - what a user whose
 * workspace was built a few days earlier runs against today's server:
 *
 *   rosidl_older_node DOMAIN SERVER
 *
 * It checks what still meets and what does not: the durable status (Status
 * has not changed) and the recent plate forces (nor has PlateForces; the
 * server hands a transient-local reader its last samples) arrive; a
 * get_state built from the old Command.msg gets no reply - the server
 * cannot read it, and says so in its log at discovery (the test script
 * checks that). Exits 0 when all three hold. */
#include <dds/dds.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dem_interfaces/msg/dds_/Command_.h"
#include "dem_interfaces/msg/dds_/PlateForces_.h"
#include "dem_interfaces/msg/dds_/Reply_.h"
#include "dem_interfaces/msg/dds_/Status_.h"
#include "typehashes.h"

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

/* Reliable, keep last `depth`, durable or not, declaring the type's hash as rmw_cyclonedds_cpp does. */
static dds_qos_t *qos(int transient_local, int depth, const char *type_hash) {
  char data[128];
  snprintf(data, sizeof data, "typehash=%s;", type_hash);
  dds_qos_t *q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(q, transient_local ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, depth);
  dds_qset_userdata(q, data, strlen(data));
  return q;
}

/* How many samples with data the reader takes within `timeout`. */
static int received(dds_entity_t reader, dds_duration_t timeout) {
  const dds_time_t deadline = dds_time() + timeout;
  int count = 0;
  while (dds_time() < deadline) {
    void *samples[16] = {NULL};
    dds_sample_info_t infos[16];
    const dds_return_t n = dds_take(reader, samples, infos, 16, 16);
    for (dds_return_t i = 0; i < n; ++i) count += infos[i].valid_data ? 1 : 0;
    if (n > 0) dds_return_loan(reader, samples, n);
    if (count > 0) return count;
    dds_sleepfor(DDS_MSECS(10));
  }
  return count;
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: rosidl_older_node DOMAIN SERVER\n");
    return 2;
  }
  const char *server = argv[2];
  const dds_entity_t participant = must(dds_create_participant((dds_domainid_t)atoi(argv[1]), NULL, NULL), "participant");
  dds_qos_t *status_qos = qos(1, 1, TYPEHASH_dem_interfaces_Status);
  dds_qos_t *plates_qos = qos(1, 1024, TYPEHASH_dem_interfaces_PlateForces);
  dds_qos_t *command_qos = qos(0, 10, TYPEHASH_dem_interfaces_Command);
  dds_qos_t *reply_qos = qos(0, 10, TYPEHASH_dem_interfaces_Reply);
  const dds_entity_t status = must(
      dds_create_reader(participant, topic(participant, &dem_interfaces_msg_dds__Status__desc, server, "status"),
                        status_qos, NULL),
      "status reader");
  const dds_entity_t plates = must(
      dds_create_reader(participant,
                        topic(participant, &dem_interfaces_msg_dds__PlateForces__desc, server, "plate_forces"),
                        plates_qos, NULL),
      "plate forces reader");
  const dds_entity_t commands = must(
      dds_create_writer(participant, topic(participant, &dem_interfaces_msg_dds__Command__desc, server, "command"),
                        command_qos, NULL),
      "command writer");
  const dds_entity_t replies = must(
      dds_create_reader(participant, topic(participant, &dem_interfaces_msg_dds__Reply__desc, server, "reply"),
                        reply_qos, NULL),
      "reply reader");

  check(received(status, DDS_SECS(20)) > 0, "the durable status arrived (Status is unchanged since 0.1.0)");
  check(received(plates, DDS_SECS(10)) > 0, "the recent plate forces arrived (PlateForces is unchanged too)");

  /* Matched by name (no XTypes type information, as rmw_cyclonedds_cpp): the server's reader is there. */
  const dds_time_t deadline = dds_time() + DDS_SECS(10);
  dds_publication_matched_status_t matched = {0};
  while (dds_time() < deadline) {
    dds_get_publication_matched_status(commands, &matched);
    if (matched.current_count > 0) break;
    dds_sleepfor(DDS_MSECS(10));
  }
  check(matched.current_count > 0, "the command writer matched the server's command reader");
  dem_interfaces_msg_dds__Command_ get_state;
  memset(&get_state, 0, sizeof get_state);
  get_state.server_ = (char *)server;
  get_state.client_id_ = "rosidl_older_node";
  get_state.request_id_ = 1;
  get_state.kind_ = 7; /* Command.GET_STATE */
  char empty[] = "";
  get_state.load_case_.path_ = get_state.load_case_.text_ = get_state.load_case_.source_name_ = empty;
  get_state.wall_velocity_.wall_ = get_state.wall_servo_.wall_ = get_state.run_until_.wall_ = empty;
  get_state.query_.wall_ = get_state.snapshot_.path_ = empty;
  get_state.parameter_.name_ = get_state.parameter_.material_ = empty;
  must(dds_write(commands, &get_state), "writing get_state");
  const int replies_seen = received(replies, DDS_SECS(3));
  printf("get_state from the 0.1.0 Command.msg: %d replies in 3 s\n", replies_seen);
  check(replies_seen == 0, "no reply: the server cannot read a 0.1.0 Command (it logged why at discovery)");

  dds_qos_t *all[] = {status_qos, plates_qos, command_qos, reply_qos};
  for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i) dds_delete_qos(all[i]);
  dds_delete(participant);
  printf("%s\n", failures == 0 ? "all checks hold" : "some checks FAILED");
  return failures == 0 ? 0 : 1;
}
