package studio.server.scene.gltf;

/** A range of a byte array, checked to lie within it: a buffer, a buffer view, the glb's BIN chunk. */
record Slice(byte[] bytes, int offset, int length) {

    Slice {
        if (offset < 0 || length < 0 || (long) offset + length > bytes.length) {
            throw new IllegalArgumentException("a slice of " + length + " bytes at " + offset + " is outside "
                    + bytes.length);
        }
    }

    static Slice of(byte[] bytes) {
        return new Slice(bytes, 0, bytes.length);
    }

    /** The {@code length} bytes at {@code at} within this slice; the caller has checked they lie within it. */
    Slice sub(long at, long length) {
        return new Slice(bytes, offset + (int) at, (int) length);
    }

    int u8(long at) {
        return bytes[offset + (int) at] & 0xff;
    }

    int u16(long at) {
        int i = offset + (int) at;
        return (bytes[i] & 0xff) | (bytes[i + 1] & 0xff) << 8;
    }

    long u32(long at) {
        int i = offset + (int) at;
        return (bytes[i] & 0xff) | (bytes[i + 1] & 0xff) << 8 | (bytes[i + 2] & 0xff) << 16
                | (long) (bytes[i + 3] & 0xff) << 24;
    }

    float f32(long at) {
        return Float.intBitsToFloat((int) u32(at));
    }
}
