// Bare-metal ATmega2560 probe for the virtual Mega's peripheral models:
// a line-oriented command interpreter on UART1 (9600 baud) that drives the
// TWI master, the sonar pins, the EEPROM, the watchdog and the LED, and
// reports what it saw. Replies are one line each.
//   q AA            address probe (START, SLA+W, STOP)     -> ack | nack
//   w AA RR BB...   write RR then the bytes                 -> ok | nack
//   s [T]           trigger T us (default 12), time the echo -> echo W D | none
//   e AAAA VV       EEPROM write                            -> ok
//   E AAAA          EEPROM read                             -> ee VV
//   n TEXT          length and byte sum of TEXT             -> len N sum S
//   b MS            busy MS ms without reading the UART     -> done
//   l 0|1           LED on PB7                              -> ok
//   d               enable a 15 ms watchdog and hang
//   W               enable a 60 ms watchdog that the main loop feeds   -> ok
//   x               the stack pointer to 0x20FF and back, a byte at a time
//                   as avr-gcc's prologues write it (SPH, SREG, SPL)  -> depth 256
// At boot: "boot MCUSR" on UART1 and "boot0" on UART0 (115200 baud).
#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/wdt.h>
#include <stdint.h>
#include <util/delay.h>
#include <util/twi.h>

namespace {

uint8_t g_mcusr;

void uart1_put(char c) {
  while (!(UCSR1A & (1 << UDRE1))) {
  }
  UDR1 = uint8_t(c);
}
void uart1_print(const char* s) {
  while (*s) uart1_put(*s++);
}
void print_hex2(uint8_t v) {
  const char* d = "0123456789ABCDEF";
  uart1_put(d[v >> 4]);
  uart1_put(d[v & 15]);
}
void print_dec(uint32_t v) {
  char buf[11];
  int n = 0;
  do {
    buf[n++] = char('0' + v % 10);
    v /= 10;
  } while (v);
  while (n) uart1_put(buf[--n]);
}
void uart0_print(const char* s) {
  while (*s) {
    while (!(UCSR0A & (1 << UDRE0))) {
    }
    UDR0 = uint8_t(*s++);
  }
}

// --- TWI master, polled -----------------------------------------------------
bool twi_wait() {
  for (uint32_t i = 0; i < 100000; ++i)
    if (TWCR & (1 << TWINT)) return true;
  return false;
}
uint8_t twi_start() {
  TWCR = (1 << TWINT) | (1 << TWSTA) | (1 << TWEN);
  twi_wait();
  return TW_STATUS;
}
uint8_t twi_send(uint8_t b) {
  TWDR = b;
  TWCR = (1 << TWINT) | (1 << TWEN);
  twi_wait();
  return TW_STATUS;
}
// simavr 1.6 reports an acknowledged SLA+W as 0x28 (data ACK) rather than
// 0x18; Arduino's Wire treats both alike, and so does the probe.
bool sla_acked(uint8_t status) { return status == TW_MT_SLA_ACK || status == TW_MT_DATA_ACK; }
void twi_stop() { TWCR = (1 << TWINT) | (1 << TWSTO) | (1 << TWEN); }

// --- sonar: Timer1 at clk/64 (4 us per count), INT4 on both edges ---------------
volatile uint16_t g_rise, g_fall;
volatile uint8_t g_edges;
ISR(INT4_vect) {
  const uint16_t t = TCNT1;
  if (PINE & (1 << PE4)) {
    g_rise = t;
    g_edges = 1;
  } else if (g_edges == 1) {
    g_fall = t;
    g_edges = 2;
  }
}

// --- parsing -------------------------------------------------------------------
const char* skip(const char* p) {
  while (*p == ' ') ++p;
  return p;
}
bool hex(const char** p, uint16_t* v) {
  const char* s = skip(*p);
  uint16_t r = 0;
  int n = 0;
  for (;; ++s, ++n) {
    char c = *s;
    uint8_t d;
    if (c >= '0' && c <= '9') d = uint8_t(c - '0');
    else if (c >= 'a' && c <= 'f') d = uint8_t(c - 'a' + 10);
    else if (c >= 'A' && c <= 'F') d = uint8_t(c - 'A' + 10);
    else break;
    r = uint16_t(r * 16 + d);
  }
  *p = s;
  if (n > 0) *v = r;
  return n > 0;
}
bool dec(const char** p, uint16_t* v) {
  const char* s = skip(*p);
  uint16_t r = 0;
  int n = 0;
  for (; *s >= '0' && *s <= '9'; ++s, ++n) r = uint16_t(r * 10 + (*s - '0'));
  *p = s;
  if (n > 0) *v = r;
  return n > 0;
}

void command(const char* line) {
  const char* p = line + 1;
  uint16_t a = 0, v = 0;
  switch (line[0]) {
    case 'q': {
      hex(&p, &a);
      const uint8_t s1 = twi_start();
      const uint8_t s2 = twi_send(uint8_t(a << 1));
      twi_stop();
      if (s1 == TW_START && sla_acked(s2)) {
        uart1_print("ack\n");
      } else {
        uart1_print("nack\n");
      }
      return;
    }
    case 'w': {
      hex(&p, &a);
      twi_start();
      bool ok = sla_acked(twi_send(uint8_t(a << 1)));
      while (ok && hex(&p, &v)) ok = twi_send(uint8_t(v)) == TW_MT_DATA_ACK;
      twi_stop();
      uart1_print(ok ? "ok\n" : "nack\n");
      return;
    }
    case 's': {
      uint16_t width = 12;
      dec(&p, &width);
      g_edges = 0;
      TCNT1 = 0;
      PORTE |= (1 << PE5);
      for (uint16_t i = 0; i < width; ++i) _delay_us(1);
      PORTE &= uint8_t(~(1 << PE5));
      const uint16_t t0 = TCNT1;
      // 70 ms at 4 us per count.
      while (g_edges != 2 && uint16_t(TCNT1 - t0) < 17500) {
      }
      if (g_edges != 2) {
        uart1_print("none\n");
        return;
      }
      uart1_print("echo ");
      print_dec(uint32_t(uint16_t(g_fall - g_rise)) * 4);
      uart1_put(' ');
      print_dec(uint32_t(uint16_t(g_rise - t0)) * 4);
      uart1_put('\n');
      return;
    }
    case 'e':
      hex(&p, &a);
      hex(&p, &v);
      eeprom_write_byte(reinterpret_cast<uint8_t*>(a), uint8_t(v));
      uart1_print("ok\n");
      return;
    case 'E':
      hex(&p, &a);
      uart1_print("ee ");
      print_hex2(eeprom_read_byte(reinterpret_cast<const uint8_t*>(a)));
      uart1_put('\n');
      return;
    case 'n': {
      p = line[1] == ' ' ? line + 2 : line + 1;
      uint32_t n = 0, sum = 0;
      for (; *p; ++p, ++n) sum += uint8_t(*p);
      uart1_print("len ");
      print_dec(n);
      uart1_print(" sum ");
      print_dec(sum);
      uart1_put('\n');
      return;
    }
    case 'b':
      dec(&p, &v);
      for (uint16_t i = 0; i < v; ++i) _delay_ms(1);
      uart1_print("done\n");
      return;
    case 'l':
      dec(&p, &v);
      if (v) PORTB |= (1 << PB7);
      else PORTB &= uint8_t(~(1 << PB7));
      uart1_print("ok\n");
      return;
    case 'x': {
      // From SP = 0x21xx to 0x2102 (same high byte), then to 0x20FF: between
      // the writes of SPH and SPL it reads 0x2002, 253 bytes below.
      const uint16_t saved = SP;
      const uint16_t near_page = 0x2102;
      const uint16_t deep = 0x20FF;
      asm volatile(
          "in r0, __SREG__\n\tcli\n\tout __SP_H__, %B0\n\tout __SREG__, r0\n\tout __SP_L__, %A0\n\t"
          "in r0, __SREG__\n\tcli\n\tout __SP_H__, %B1\n\tout __SREG__, r0\n\tout __SP_L__, %A1\n\t"
          "in r0, __SREG__\n\tcli\n\tout __SP_H__, %B2\n\tout __SREG__, r0\n\tout __SP_L__, %A2\n\t"
          :
          : "r"(near_page), "r"(deep), "r"(saved)
          : "r0", "memory");
      uart1_print("depth ");
      print_dec(RAMEND - deep);
      uart1_put('\n');
      return;
    }
    case 'd':
      wdt_enable(WDTO_15MS);
      for (;;) {
      }
    case 'W':
      wdt_enable(WDTO_60MS);
      uart1_print("ok\n");
      return;
    default:
      uart1_print("err\n");
  }
}

}  // namespace

int main() {
  g_mcusr = MCUSR;
  MCUSR = 0;
  wdt_disable();
  // UART1 9600 and UART0 115200, both with U2X as the Arduino core does.
  UCSR1A = (1 << U2X1);
  UBRR1 = 207;
  UCSR1B = (1 << RXEN1) | (1 << TXEN1);
  UCSR1C = (1 << UCSZ11) | (1 << UCSZ10);
  UCSR0A = (1 << U2X0);
  UBRR0 = 16;
  UCSR0B = (1 << RXEN0) | (1 << TXEN0);
  UCSR0C = (1 << UCSZ01) | (1 << UCSZ00);
  // TWI 400 kHz: 16 MHz / (16 + 2 * 12).
  TWSR = 0;
  TWBR = 12;
  // Sonar: PE5 trigger out, PE4 echo in with INT4 on any edge; Timer1 clk/64.
  DDRE |= (1 << PE5);
  EICRB = (EICRB & uint8_t(~((1 << ISC41) | (1 << ISC40)))) | (1 << ISC40);
  EIMSK |= (1 << INT4);
  TCCR1A = 0;
  TCCR1B = (1 << CS11) | (1 << CS10);
  DDRB |= (1 << PB7);
  sei();

  uart1_print("boot ");
  print_hex2(g_mcusr);
  uart1_put('\n');
  uart0_print("boot0\n");

  char line[160];
  uint8_t n = 0;
  for (;;) {
    wdt_reset();
    if (!(UCSR1A & (1 << RXC1))) continue;
    const char c = char(UDR1);
    if (c == '\n' || c == '\r') {
      if (n == 0) continue;
      line[n] = 0;
      command(line);
      n = 0;
    } else if (n < sizeof line - 1) {
      line[n++] = c;
    }
  }
}
