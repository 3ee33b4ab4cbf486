/*
 * goto-goal: a Player 1.5 client of the manual's appendix A C API, written
 * as a 2004 program would be: it sends a goal to a wavefront device as a
 * position command and polls the device's stall flag until the robot has
 * driven and stopped.
 *
 *   goto-goal HOST PORT INDEX X_MM Y_MM YAW_DEG
 *
 * Exit status: 0 arrived (the final pose on stdout), 1 connection or
 * protocol failure, 2 usage, 3 no arrival within the message budget.
 */
#include <arpa/inet.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "playercclient.h"

enum { kMaxMessages = 20000 }; /* about 10 minutes of 10 Hz data from a few devices */

static int32_t field(const char* payload, int offset) {
  uint32_t value;
  memcpy(&value, payload + offset, sizeof value);
  return (int32_t)ntohl(value);
}

int main(int argc, char** argv) {
  player_connection_t conn;
  player_position_cmd_t goal;
  player_msghdr_t hdr;
  char payload[PLAYER_MAX_PAYLOAD_SIZE];
  uint8_t granted = 0;
  int index, messages, driving = 0;

  if (argc != 7) {
    fprintf(stderr, "usage: goto-goal HOST PORT INDEX X_MM Y_MM YAW_DEG\n");
    return 2;
  }
  index = atoi(argv[3]);
  if (player_connect(&conn, argv[1], atoi(argv[2])) != 0) {
    fprintf(stderr, "goto-goal: cannot connect to %s:%s\n", argv[1], argv[2]);
    return 1;
  }
  if (player_request_device_access(&conn, PLAYER_POSITION_CODE, (uint16_t)index, 'a', &granted) != 0 ||
      granted != 'a') {
    fprintf(stderr, "goto-goal: position:%d not granted (got '%c')\n", index, granted ? granted : '?');
    player_disconnect(&conn);
    return 1;
  }

  memset(&goal, 0, sizeof goal);
  goal.xpos = (int32_t)htonl((uint32_t)atoi(argv[4]));
  goal.ypos = (int32_t)htonl((uint32_t)atoi(argv[5]));
  goal.yaw = (int32_t)htonl((uint32_t)atoi(argv[6]));
  goal.state = 1;
  goal.type = 1;
  if (player_write(&conn, PLAYER_POSITION_CODE, (uint16_t)index, (const char*)&goal, sizeof goal) != 0) {
    fprintf(stderr, "goto-goal: the goal could not be sent\n");
    player_disconnect(&conn);
    return 1;
  }

  for (messages = 0; messages < kMaxMessages; ++messages) {
    if (player_read(&conn, &hdr, payload, sizeof payload) != 0) {
      fprintf(stderr, "goto-goal: the connection broke\n");
      player_disconnect(&conn);
      return 1;
    }
    if (hdr.type != PLAYER_MSGTYPE_DATA || hdr.device != PLAYER_POSITION_CODE || hdr.device_index != index ||
        hdr.size < 25) {
      continue;
    }
    /* player_position_data_t: xpos ypos yaw xspeed yspeed yawspeed (int32), stall (uint8) */
    if (payload[24] == 0) {
      driving = 1;
    } else if (driving) {
      printf("arrived at %d %d %d\n", field(payload, 0), field(payload, 4), field(payload, 8));
      player_disconnect(&conn);
      return 0;
    }
  }
  fprintf(stderr, "goto-goal: no arrival after %d messages\n", kMaxMessages);
  player_disconnect(&conn);
  return 3;
}
