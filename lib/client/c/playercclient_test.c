/*
 * The C API checked from C, against a real server (see playercclient_test.h).
 * Every loop is bounded: reads stop after kMaxReads messages.
 */
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "playercclient.h"
#include "playercclient_test.h"

enum { kMaxReads = 200, kGuard = 16, kGuardByte = 0xA5 };

static char failure[512];

#define CHECK(condition)                                                                       \
  do {                                                                                         \
    if (!(condition)) {                                                                        \
      snprintf(failure, sizeof failure, "%s:%d: %s", __FILE__, __LINE__, #condition);          \
      return failure;                                                                          \
    }                                                                                          \
  } while (0)

#define CHECK_EQ(actual, expected)                                                             \
  do {                                                                                         \
    long long actual_value = (long long)(actual), expected_value = (long long)(expected);     \
    if (actual_value != expected_value) {                                                      \
      snprintf(failure, sizeof failure, "%s:%d: %s is %lld, expected %s (%lld)", __FILE__,     \
               __LINE__, #actual, actual_value, #expected, expected_value);                    \
      return failure;                                                                          \
    }                                                                                          \
  } while (0)

#define CHECK_OK(call) CHECK_EQ(call, 0)
#define CHECK_FAILS(call) CHECK_EQ(call, -1)

static int connect_to(const pcc_server* server, player_connection_t* conn) {
  return player_connect(conn, "127.0.0.1", server->port);
}

/* Reads until a message of this type from this device, at most kMaxReads. */
static int read_until(player_connection_t* conn, uint16_t type, uint16_t device,
                      player_msghdr_t* hdr, char* payload, size_t payloadlen) {
  int reads;
  for (reads = 0; reads < kMaxReads; ++reads) {
    if (player_read(conn, hdr, payload, payloadlen) != 0) return -1;
    if (hdr->type == type && hdr->device == device) return 0;
  }
  return -1;
}

static int guard_intact(const unsigned char* guard) {
  int i;
  for (i = 0; i < kGuard; ++i) {
    if (guard[i] != kGuardByte) return 0;
  }
  return 1;
}

/* A loopback port nobody listens on: bound, then released. */
static int closed_port(void) {
  struct sockaddr_in address;
  socklen_t length = sizeof address;
  int port = -1;
  int probe = socket(AF_INET, SOCK_STREAM, 0);
  if (probe < 0) return -1;
  memset(&address, 0, sizeof address);
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (bind(probe, (struct sockaddr*)&address, sizeof address) == 0 &&
      getsockname(probe, (struct sockaddr*)&address, &length) == 0) {
    port = ntohs(address.sin_port);
  }
  close(probe);
  return port;
}

const char* pcc_check_connect_reads_banner_and_socket(const pcc_server* server) {
  player_connection_t conn;
  player_msghdr_t hdr;
  struct sockaddr_in peer;
  socklen_t peer_length = sizeof peer;
  struct pollfd watch;
  int i;

  /* As the appendix writes it: a host name. */
  CHECK_OK(player_connect(&conn, "localhost", server->port));
  CHECK(memcmp(conn.banner, "Player v.1.5", 12) == 0);
  for (i = 12; i < PLAYER_IDENT_STRLEN; ++i) CHECK_EQ(conn.banner[i], 0);
  CHECK(conn.impl != NULL);

  /* sock is the connection itself: its peer is the server... */
  CHECK(conn.sock >= 0);
  CHECK_OK(getpeername(conn.sock, (struct sockaddr*)&peer, &peer_length));
  CHECK_EQ(peer.sin_family, AF_INET);
  CHECK_EQ(ntohs(peer.sin_port), server->port);
  /* ...and poll() sees the server's data rounds (push mode, 10 Hz) arrive. */
  watch.fd = conn.sock;
  watch.events = POLLIN;
  watch.revents = 0;
  CHECK_EQ(poll(&watch, 1, 5000), 1);
  CHECK(watch.revents & POLLIN);

  /* The first message is the SYNCH of a round with nothing subscribed. */
  CHECK_OK(player_read(&conn, &hdr, NULL, 0));
  CHECK_EQ(hdr.stx, PLAYER_STXX);
  CHECK_EQ(hdr.type, PLAYER_MSGTYPE_SYNCH);
  CHECK_EQ(hdr.device, PLAYER_PLAYER_CODE);
  CHECK_EQ(hdr.size, 0);
  /* Host order: the server's clock reads as today, not as swapped bytes. */
  CHECK(hdr.time_sec > (uint32_t)time(NULL) - 3600 && hdr.time_sec < (uint32_t)time(NULL) + 3600);
  CHECK(hdr.time_usec < 1000000);

  CHECK_OK(player_disconnect(&conn));
  CHECK_EQ(conn.sock, -1);
  CHECK(conn.impl == NULL);
  return NULL;
}

const char* pcc_check_connect_failures(void) {
  player_connection_t conn;
  player_msghdr_t hdr;
  const int nobody = closed_port();
  CHECK(nobody > 0);

  conn.sock = 12345; /* whatever was there is replaced */
  CHECK_FAILS(player_connect(&conn, "127.0.0.1", nobody));
  CHECK_EQ(conn.sock, -1);
  CHECK(conn.impl == NULL);
  /* A connection that never opened cannot be used or closed. */
  CHECK_FAILS(player_read(&conn, &hdr, NULL, 0));
  CHECK_FAILS(player_disconnect(&conn));

  CHECK_FAILS(player_connect(&conn, "127.0.0.1", 0));
  CHECK_FAILS(player_connect(&conn, "127.0.0.1", 70000));
  CHECK_FAILS(player_connect(&conn, "127.0.0.1", -1));
  CHECK_FAILS(player_connect(&conn, NULL, PLAYER_PORTNUM));
  CHECK_EQ(conn.sock, -1);
  CHECK_FAILS(player_connect(NULL, "127.0.0.1", PLAYER_PORTNUM));
  CHECK_FAILS(player_disconnect(NULL));
  return NULL;
}

const char* pcc_check_device_access(const pcc_server* server) {
  player_connection_t conn;
  uint8_t granted = 0;

  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_request_device_access(&conn, PLAYER_LASER_CODE, 0, PLAYER_READ_MODE, &granted));
  CHECK_EQ(granted, 'r');
  CHECK_OK(player_request_device_access(&conn, PLAYER_SONAR_CODE, 0, PLAYER_ALL_MODE, &granted));
  CHECK_EQ(granted, 'a');
  /* The server has no ptz: the call works, the grant says it failed. */
  granted = 0;
  CHECK_OK(player_request_device_access(&conn, PLAYER_PTZ_CODE, 0, PLAYER_ALL_MODE, &granted));
  CHECK_EQ(granted, PLAYER_ERROR_MODE);
  /* grant_access may be NULL, whatever is granted. */
  CHECK_OK(player_request_device_access(&conn, PLAYER_POSITION_CODE, 0, 'w', NULL));
  CHECK_OK(player_request_device_access(&conn, PLAYER_PTZ_CODE, 1, 'r', NULL));
  CHECK_OK(player_request_device_access(&conn, PLAYER_LASER_CODE, 0, PLAYER_CLOSE_MODE, &granted));
  CHECK_EQ(granted, 'c');
  CHECK_OK(player_disconnect(&conn));
  return NULL;
}

const char* pcc_check_read_data_header_in_host_order(const pcc_server* server) {
  /* A big-endian uint32 0x12345678, then a uint16 0x0102, then text. */
  static const unsigned char published[] = {0x12, 0x34, 0x56, 0x78, 0x01, 0x02, 'h', 'i'};
  player_connection_t conn;
  player_msghdr_t hdr;
  unsigned char buffer[64 + kGuard];
  uint32_t first_field;
  uint16_t second_field;

  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_request_device_access(&conn, PLAYER_LASER_CODE, 0, 'r', NULL));
  CHECK_OK(server->publish_laser(server->context, published, sizeof published, 1086000000u, 250000u));

  memset(buffer, kGuardByte, sizeof buffer);
  CHECK_OK(read_until(&conn, PLAYER_MSGTYPE_DATA, PLAYER_LASER_CODE, &hdr, (char*)buffer, 64));
  CHECK_EQ(hdr.stx, PLAYER_STXX);
  CHECK_EQ(hdr.device_index, 0);
  CHECK_EQ(hdr.size, sizeof published);
  CHECK_EQ(hdr.timestamp_sec, 1086000000u);
  CHECK_EQ(hdr.timestamp_usec, 250000u);
  CHECK_EQ(hdr.reserved, 0);
  /* The payload is left as it came: network order. */
  CHECK(memcmp(buffer, published, sizeof published) == 0);
  memcpy(&first_field, buffer, 4);
  memcpy(&second_field, buffer + 4, 2);
  CHECK_EQ(ntohl(first_field), 0x12345678u);
  CHECK_EQ(ntohs(second_field), 0x0102);
  CHECK_EQ(buffer[sizeof published], kGuardByte); /* nothing past the payload */

  /* Then the SYNCH that ends the round. */
  CHECK_OK(player_read(&conn, &hdr, (char*)buffer, 64));
  CHECK_EQ(hdr.type, PLAYER_MSGTYPE_SYNCH);
  CHECK_OK(player_disconnect(&conn));
  return NULL;
}

const char* pcc_check_read_cuts_long_payloads(const pcc_server* server) {
  unsigned char published[100];
  unsigned char buffer[10 + kGuard];
  player_connection_t conn;
  player_msghdr_t hdr;
  size_t i;

  for (i = 0; i < sizeof published; ++i) published[i] = (unsigned char)(i * 3 + 1);
  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_request_device_access(&conn, PLAYER_LASER_CODE, 0, 'r', NULL));
  CHECK_OK(server->publish_laser(server->context, published, sizeof published, 7u, 0u));

  memset(buffer, kGuardByte, sizeof buffer);
  CHECK_OK(read_until(&conn, PLAYER_MSGTYPE_DATA, PLAYER_LASER_CODE, &hdr, (char*)buffer, 10));
  CHECK_EQ(hdr.size, 100); /* the real length */
  CHECK(memcmp(buffer, published, 10) == 0);
  CHECK(guard_intact(buffer + 10));
  /* The rest of the message is gone, not read as the next one. */
  CHECK_OK(player_read(&conn, &hdr, (char*)buffer, 10));
  CHECK_EQ(hdr.stx, PLAYER_STXX);
  CHECK_EQ(hdr.type, PLAYER_MSGTYPE_SYNCH);
  CHECK(guard_intact(buffer + 10));
  CHECK_OK(player_disconnect(&conn));
  return NULL;
}

const char* pcc_check_write_command(const pcc_server* server) {
  player_connection_t conn;
  player_position_cmd_t cmd;
  unsigned char received[sizeof cmd + kGuard];
  size_t received_length = 0;
  uint8_t granted = 0;

  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_request_device_access(&conn, PLAYER_POSITION_CODE, 0, 'a', &granted));
  CHECK_EQ(granted, 'a');
  memset(&cmd, 0, sizeof cmd);
  cmd.xspeed = (int32_t)htonl(300);
  cmd.yawspeed = (int32_t)htonl((uint32_t)-40);
  cmd.state = 1;
  CHECK_OK(player_write(&conn, PLAYER_POSITION_CODE, 0, (const char*)&cmd, sizeof cmd));
  /* The driver has exactly the bytes sent, header and all stripped. */
  CHECK_OK(server->position_command(server->context, received, sizeof received, &received_length));
  CHECK_EQ(received_length, sizeof cmd);
  CHECK(memcmp(received, &cmd, sizeof cmd) == 0);
  CHECK_OK(player_disconnect(&conn));
  return NULL;
}

const char* pcc_check_write_refuses_bad_commands(const pcc_server* server) {
  static char oversized[PLAYER_MAX_PAYLOAD_SIZE + 1];
  player_connection_t conn;
  player_position_cmd_t cmd;
  unsigned char received[sizeof cmd + kGuard];
  size_t received_length = 0;
  uint8_t granted = 0;

  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_request_device_access(&conn, PLAYER_POSITION_CODE, 0, 'a', &granted));
  CHECK_FAILS(player_write(&conn, PLAYER_POSITION_CODE, 0, oversized, sizeof oversized));
  CHECK_FAILS(player_write(&conn, PLAYER_POSITION_CODE, 0, NULL, 26));
  CHECK_FAILS(player_write(NULL, PLAYER_POSITION_CODE, 0, oversized, 26));
  /* Refused before sending: the connection is still in step, and the first
   * command the device gets is the next good one. */
  memset(&cmd, 0, sizeof cmd);
  cmd.xspeed = (int32_t)htonl(123);
  CHECK_OK(player_write(&conn, PLAYER_POSITION_CODE, 0, (const char*)&cmd, sizeof cmd));
  CHECK_OK(server->position_command(server->context, received, sizeof received, &received_length));
  CHECK_EQ(received_length, sizeof cmd);
  CHECK(memcmp(received, &cmd, sizeof cmd) == 0);
  CHECK_OK(player_disconnect(&conn));
  return NULL;
}

const char* pcc_check_request_and_replies(const pcc_server* server) {
  static const char ping[] = {1, 'p', 'i', 'n', 'g'};
  static const char refused[] = {2, 'n', 'o'};
  static const char datafreq[] = {0, PLAYER_PLAYER_DATAFREQ_REQ, 0, 20};
  player_connection_t conn;
  player_msghdr_t replyhdr;
  char reply[64 + kGuard];

  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_request_device_access(&conn, PLAYER_SONAR_CODE, 0, 'a', NULL));

  /* The echo driver ACKs subtype 1 with the request's own bytes. */
  memset(reply, kGuardByte, sizeof reply);
  CHECK_OK(player_request(&conn, PLAYER_SONAR_CODE, 0, ping, sizeof ping, &replyhdr, reply, 64));
  CHECK_EQ(replyhdr.stx, PLAYER_STXX);
  CHECK_EQ(replyhdr.type, PLAYER_MSGTYPE_RESP_ACK);
  CHECK_EQ(replyhdr.device, PLAYER_SONAR_CODE);
  CHECK_EQ(replyhdr.device_index, 0);
  CHECK_EQ(replyhdr.size, sizeof ping);
  CHECK(memcmp(reply, ping, sizeof ping) == 0);
  CHECK_EQ((unsigned char)reply[sizeof ping], kGuardByte);

  /* A reply longer than the buffer is cut, never overruns it. */
  memset(reply, kGuardByte, sizeof reply);
  CHECK_OK(player_request(&conn, PLAYER_SONAR_CODE, 0, ping, sizeof ping, &replyhdr, reply, 3));
  CHECK_EQ(replyhdr.size, sizeof ping);
  CHECK(memcmp(reply, ping, 3) == 0);
  CHECK(guard_intact((unsigned char*)reply + 3));

  /* A NACK is an answer: 0, and the header says NACK. */
  CHECK_OK(player_request(&conn, PLAYER_SONAR_CODE, 0, refused, sizeof refused, &replyhdr, reply, 64));
  CHECK_EQ(replyhdr.type, PLAYER_MSGTYPE_RESP_NACK);
  /* Neither reply buffer is needed. */
  CHECK_OK(player_request(&conn, PLAYER_SONAR_CODE, 0, ping, sizeof ping, NULL, NULL, 0));
  CHECK_OK(player_request(&conn, PLAYER_SONAR_CODE, 0, ping, sizeof ping, NULL, reply, 64));
  CHECK(memcmp(reply, ping, sizeof ping) == 0);
  /* A device this client has not opened: the server's ERR, empty. */
  CHECK_OK(player_request(&conn, PLAYER_POSITION_CODE, 0, ping, sizeof ping, &replyhdr, reply, 64));
  CHECK_EQ(replyhdr.type, PLAYER_MSGTYPE_RESP_ERR);
  CHECK_EQ(replyhdr.device, PLAYER_POSITION_CODE);
  CHECK_EQ(replyhdr.size, 0);
  /* The player device, its uint16 subtype in network order. */
  CHECK_OK(player_request(&conn, PLAYER_PLAYER_CODE, 0, datafreq, sizeof datafreq, &replyhdr, reply, 64));
  CHECK_EQ(replyhdr.type, PLAYER_MSGTYPE_RESP_ACK);
  CHECK_EQ(replyhdr.device, PLAYER_PLAYER_CODE);
  CHECK_OK(player_disconnect(&conn));
  return NULL;
}

const char* pcc_check_request_refuses_bad_payloads(const pcc_server* server) {
  static char oversized[PLAYER_MAX_PAYLOAD_SIZE + 1];
  static const char ping[] = {1, 'p'};
  player_connection_t conn;
  player_msghdr_t replyhdr;

  oversized[0] = 1;
  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_request_device_access(&conn, PLAYER_SONAR_CODE, 0, 'a', NULL));
  CHECK_FAILS(player_request(&conn, PLAYER_SONAR_CODE, 0, oversized, sizeof oversized, &replyhdr, NULL, 0));
  CHECK_FAILS(player_request(&conn, PLAYER_SONAR_CODE, 0, NULL, 4, &replyhdr, NULL, 0));
  /* A 1.5 server never answers an empty message: refused, not a hang. */
  CHECK_FAILS(player_request(&conn, PLAYER_SONAR_CODE, 0, ping, 0, &replyhdr, NULL, 0));
  /* Refused before sending: the connection is still in step. */
  CHECK_OK(player_request(&conn, PLAYER_SONAR_CODE, 0, ping, sizeof ping, &replyhdr, NULL, 0));
  CHECK_EQ(replyhdr.type, PLAYER_MSGTYPE_RESP_ACK);
  CHECK_EQ(replyhdr.size, sizeof ping);
  CHECK_OK(player_disconnect(&conn));
  return NULL;
}

const char* pcc_check_use_after_disconnect(const pcc_server* server) {
  static const char ping[] = {1, 'p'};
  player_connection_t conn;
  player_msghdr_t hdr;
  char buffer[16];
  uint8_t granted = 'x';

  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_disconnect(&conn));
  CHECK_EQ(conn.sock, -1);
  CHECK_FAILS(player_read(&conn, &hdr, buffer, sizeof buffer));
  CHECK_FAILS(player_write(&conn, PLAYER_POSITION_CODE, 0, ping, sizeof ping));
  CHECK_FAILS(player_request(&conn, PLAYER_SONAR_CODE, 0, ping, sizeof ping, &hdr, buffer, sizeof buffer));
  CHECK_FAILS(player_request_device_access(&conn, PLAYER_LASER_CODE, 0, 'r', &granted));
  CHECK_EQ(granted, 'x'); /* untouched */
  CHECK_FAILS(player_disconnect(&conn));
  /* The same struct connects again. */
  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_request_device_access(&conn, PLAYER_LASER_CODE, 0, 'r', &granted));
  CHECK_EQ(granted, 'r');
  CHECK_OK(player_disconnect(&conn));
  return NULL;
}

const char* pcc_check_lost_connection(const pcc_server* server) {
  player_connection_t conn;
  player_msghdr_t hdr;
  int reads = 0;

  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(player_request_device_access(&conn, PLAYER_LASER_CODE, 0, 'r', NULL));
  CHECK_OK(server->stop(server->context));
  /* What arrived before the close can still be read; then -1, no hang. */
  while (reads < kMaxReads && player_read(&conn, &hdr, NULL, 0) == 0) ++reads;
  CHECK(reads < kMaxReads);
  CHECK_FAILS(player_request_device_access(&conn, PLAYER_LASER_CODE, 0, 'r', NULL));
  /* Still ours to release. */
  CHECK_OK(player_disconnect(&conn));
  return NULL;
}

const char* pcc_check_debug_level(void) {
  CHECK_EQ(player_debug_level(-1), PLAYER_CCLIENT_DEBUG_LEVEL_DEFAULT);
  CHECK_EQ(player_debug_level(-1), 5); /* -1 only asks */
  CHECK_EQ(player_debug_level(0), 5);  /* the previous level */
  CHECK_EQ(player_debug_level(-1), 0);
  CHECK_EQ(player_debug_level(3), 0);
  CHECK_EQ(player_debug_level(-7), 3); /* any negative level only asks */
  CHECK_EQ(player_debug_level(5), 3);
  return NULL;
}

/* What a call printed on stderr (file descriptor 2), up to capacity - 1 bytes. */
typedef int (*stderr_action)(const void* argument);

static int capture_stderr(stderr_action action, const void* argument, char* text, size_t capacity) {
  FILE* sink = tmpfile();
  int saved;
  size_t length;
  if (sink == NULL) return -1;
  fflush(stderr);
  saved = dup(2);
  if (saved < 0 || dup2(fileno(sink), 2) < 0) {
    fclose(sink);
    return -1;
  }
  action(argument);
  fflush(stderr);
  dup2(saved, 2);
  close(saved);
  rewind(sink);
  length = fread(text, 1, capacity - 1, sink);
  text[length] = '\0';
  fclose(sink);
  return 0;
}

static int connect_to_port(const void* argument) {
  player_connection_t conn;
  return player_connect(&conn, "127.0.0.1", *(const int*)argument);
}

static int ask_ptz_without_grant(const void* argument) {
  return player_request_device_access((player_connection_t*)argument, PLAYER_PTZ_CODE, 0, 'a', NULL);
}

const char* pcc_check_diagnostics_follow_debug_level(const pcc_server* server) {
  char text[1024];
  char port_text[16];
  player_connection_t conn;
  const int nobody = closed_port();
  const int previous = player_debug_level(0);
  CHECK(nobody > 0);
  snprintf(port_text, sizeof port_text, "%d", nobody);

  /* Errors: silent at 0, one line naming the call and the port at 1. */
  CHECK_OK(capture_stderr(connect_to_port, &nobody, text, sizeof text));
  CHECK_EQ(strlen(text), 0);
  player_debug_level(1);
  CHECK_OK(capture_stderr(connect_to_port, &nobody, text, sizeof text));
  CHECK(strstr(text, "player_connect(): ") == text);
  CHECK(strstr(text, port_text) != NULL);

  /* Warnings (access other than asked for) from level 2 on. */
  CHECK_OK(connect_to(server, &conn));
  CHECK_OK(capture_stderr(ask_ptz_without_grant, &conn, text, sizeof text));
  CHECK_EQ(strlen(text), 0);
  player_debug_level(2);
  CHECK_OK(capture_stderr(ask_ptz_without_grant, &conn, text, sizeof text));
  CHECK(strstr(text, "player_request_device_access(): ") == text);
  CHECK(strstr(text, "'a'") != NULL && strstr(text, "'e'") != NULL);
  CHECK_OK(player_disconnect(&conn));

  player_debug_level(previous);
  return NULL;
}
