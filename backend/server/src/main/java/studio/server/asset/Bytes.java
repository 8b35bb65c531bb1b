package studio.server.asset;

/** Integers read from a byte array at an offset, in the byte order a format uses (the caller checks bounds). */
final class Bytes {

    private Bytes() {
    }

    static int bigEndianInt(byte[] b, int at) {
        return (b[at] & 0xff) << 24 | (b[at + 1] & 0xff) << 16 | (b[at + 2] & 0xff) << 8 | (b[at + 3] & 0xff);
    }

    static int bigEndianShort(byte[] b, int at) {
        return (b[at] & 0xff) << 8 | (b[at + 1] & 0xff);
    }
}
