/*
 * Compiled as strict C89 (-std=c89 -pedantic-errors): the header must build
 * for a 2004 C program, and the appendix's fragments must work as written.
 */
#include <netinet/in.h> /* htonl, htons: the caller byte-swaps payloads */
#include <stddef.h>
#include <string.h>

#include "playercclient.h"
#include "playercclient_test.h"

/* Sizes and offsets from wire-format.md. */
const char* pcc_c89_check_struct_layouts(void)
{
  if (sizeof(player_msghdr_t) != 32) return "sizeof(player_msghdr_t) != 32";
  if (offsetof(player_msghdr_t, time_sec) != 8) return "player_msghdr_t.time_sec not at 8";
  if (offsetof(player_msghdr_t, reserved) != 24) return "player_msghdr_t.reserved not at 24";
  if (offsetof(player_msghdr_t, size) != 28) return "player_msghdr_t.size not at 28";
  if (sizeof(player_device_id_t) != 6) return "sizeof(player_device_id_t) != 6";
  if (sizeof(player_device_devlist_t) != 388) return "sizeof(player_device_devlist_t) != 388";
  if (sizeof(player_device_driverinfo_t) != 72) return "sizeof(player_device_driverinfo_t) != 72";
  if (offsetof(player_device_driverinfo_t, driver_name) != 8) return "driverinfo.driver_name not at 8";
  if (sizeof(player_device_req_t) != 7) return "sizeof(player_device_req_t) != 7";
  if (offsetof(player_device_req_t, access) != 6) return "player_device_req_t.access not at 6";
  if (sizeof(player_device_resp_t) != 71) return "sizeof(player_device_resp_t) != 71";
  if (offsetof(player_device_resp_t, driver_name) != 7) return "player_device_resp_t.driver_name not at 7";
  if (sizeof(player_device_data_req_t) != 2) return "sizeof(player_device_data_req_t) != 2";
  if (sizeof(player_device_datamode_req_t) != 3) return "sizeof(player_device_datamode_req_t) != 3";
  if (sizeof(player_device_datafreq_req_t) != 4) return "sizeof(player_device_datafreq_req_t) != 4";
  if (sizeof(player_device_auth_req_t) != 34) return "sizeof(player_device_auth_req_t) != 34";
  if (sizeof(player_device_nameservice_req_t) != 68) return "sizeof(player_device_nameservice_req_t) != 68";
  if (offsetof(player_device_nameservice_req_t, port) != 66) return "nameservice.port not at 66";
  if (sizeof(player_position_cmd_t) != 26) return "sizeof(player_position_cmd_t) != 26";
  if (offsetof(player_position_cmd_t, yawspeed) != 20) return "player_position_cmd_t.yawspeed not at 20";
  if (offsetof(player_position_cmd_t, type) != 25) return "player_position_cmd_t.type not at 25";
  return NULL;
}

/*
 * Appendix A's fragments strung together (with 1.5's position command
 * fields: the manual's speed/turnrate belong to an older Player), and
 * the command checked byte for byte on the server's side.
 */
const char* pcc_c89_appendix_example(const pcc_server* server)
{
  player_connection_t conn;
  player_msghdr_t hdr;
  char data[PLAYER_MAX_MESSAGE_SIZE];
  player_position_cmd_t cmd;
  unsigned char received[sizeof(player_position_cmd_t) + 1];
  size_t received_length = 0;

  /* Connect to Player server */
  if (player_connect(&conn, "localhost", server->port))
    return "player_connect failed";

  /* Request 'all' access to the ptz device (this server has none: 'e') */
  if (player_request_device_access(&conn, PLAYER_PTZ_CODE, 0, 'a', NULL) == -1)
    return "player_request_device_access(ptz) failed";
  if (player_request_device_access(&conn, PLAYER_POSITION_CODE, 0, 'a', NULL) == -1)
    return "player_request_device_access(position) failed";

  if (player_read(&conn, &hdr, data, sizeof(data)) == -1)
    return "player_read failed";
  if (hdr.stx != PLAYER_STXX)
    return "player_read gave a header whose stx is not PLAYER_STXX";

  memset(&cmd, 0, sizeof(cmd));
  cmd.xspeed = (int32_t)htonl(0);
  cmd.yawspeed = (int32_t)htonl(40);
  if (player_write(&conn, PLAYER_POSITION_CODE, 0, (char*)&cmd,
                   sizeof(player_position_cmd_t)) == -1)
    return "player_write failed";
  if (server->position_command(server->context, received, sizeof(received), &received_length))
    return "no command reached position:0";
  if (received_length != sizeof(cmd) || memcmp(received, &cmd, sizeof(cmd)) != 0)
    return "position:0 got other bytes than player_write sent";

  if (player_disconnect(&conn))
    return "player_disconnect failed";
  return NULL;
}
