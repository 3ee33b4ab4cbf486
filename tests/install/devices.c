/*
 * A Player 1.5 C client built against an installed playerkit by
 * tests/bats/install.bats, as a 2004 program would be: #include <playercclient.h>.
 * Lists the server's devices and prints the first position:0 reading.
 *   devices_c HOST PORT
 */
#include <arpa/inet.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <playercclient.h>

int main(int argc, char** argv) {
  player_connection_t conn;
  player_msghdr_t hdr;
  player_device_devlist_t list;
  char data[PLAYER_MAX_MESSAGE_SIZE];
  uint16_t subtype = htons(PLAYER_PLAYER_DEVLIST_REQ);
  uint8_t granted = 0;
  int i;
  int32_t xpos, ypos;

  if (argc != 3) {
    fprintf(stderr, "usage: devices_c HOST PORT\n");
    return 2;
  }
  if (player_connect(&conn, argv[1], atoi(argv[2])) == -1) return 1;
  memset(&list, 0, sizeof(list));
  if (player_request(&conn, PLAYER_PLAYER_CODE, 0, (const char*)&subtype, sizeof(subtype), &hdr,
                     (char*)&list, sizeof(list)) == -1 ||
      hdr.type != PLAYER_MSGTYPE_RESP_ACK) {
    fprintf(stderr, "devices_c: no device list\n");
    return 1;
  }
  for (i = 0; i < ntohs(list.device_count) && i < PLAYER_MAX_DEVICES; ++i) {
    printf("device %u:%u\n", ntohs(list.devices[i].code), ntohs(list.devices[i].index));
  }
  if (player_request_device_access(&conn, PLAYER_POSITION_CODE, 0, PLAYER_READ_MODE, &granted) == -1 ||
      granted != PLAYER_READ_MODE) {
    fprintf(stderr, "devices_c: position:0 not opened\n");
    return 1;
  }
  for (i = 0; i < 100; ++i) {
    if (player_read(&conn, &hdr, data, sizeof(data)) == -1) return 1;
    if (hdr.type == PLAYER_MSGTYPE_DATA && hdr.device == PLAYER_POSITION_CODE && hdr.device_index == 0) {
      /* player_position_data_t: xpos, ypos (int32, mm, network order) first. */
      memcpy(&xpos, data, 4);
      memcpy(&ypos, data + 4, 4);
      printf("position:0 xpos=%ld ypos=%ld\n", (long)(int32_t)ntohl((uint32_t)xpos),
             (long)(int32_t)ntohl((uint32_t)ypos));
      player_disconnect(&conn);
      return 0;
    }
  }
  fprintf(stderr, "devices_c: no position:0 data\n");
  return 1;
}
