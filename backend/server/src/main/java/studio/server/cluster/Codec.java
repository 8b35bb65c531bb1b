package studio.server.cluster;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * How one type of value is written into the cluster as bytes, field by field, and read back: no Java
 * serialization, so nothing read from the cluster chooses a class to load.
 */
interface Codec<V> {

    void write(DataOutputStream out, V value) throws IOException;

    V read(DataInputStream in) throws IOException;

    /** The bytes of a value. */
    default byte[] encode(V value) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(64);
        try (DataOutputStream out = new DataOutputStream(bytes)) {
            write(out, value);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return bytes.toByteArray();
    }

    /**
     * The value of bytes this codec wrote.
     *
     * @throws IOException if they are not such bytes (short, or with bytes left over)
     */
    default V decode(byte[] bytes) throws IOException {
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(bytes));
        V value = read(in);
        if (in.available() != 0) {
            throw new IOException("bytes left over");
        }
        return value;
    }

    /** Raw bytes, as they are (a scene's JSON, an image). */
    Codec<byte[]> BYTES = new Codec<>() {
        @Override
        public void write(DataOutputStream out, byte[] value) throws IOException {
            out.write(value);
        }

        @Override
        public byte[] read(DataInputStream in) throws IOException {
            return in.readAllBytes();
        }
    };

    Codec<String> STRING = new Codec<>() {
        @Override
        public void write(DataOutputStream out, String value) throws IOException {
            out.writeUTF(value);
        }

        @Override
        public String read(DataInputStream in) throws IOException {
            return in.readUTF();
        }
    };

    Codec<Long> LONG = new Codec<>() {
        @Override
        public void write(DataOutputStream out, Long value) throws IOException {
            out.writeLong(value);
        }

        @Override
        public Long read(DataInputStream in) throws IOException {
            return in.readLong();
        }
    };

    static void writeNullable(DataOutputStream out, String value) throws IOException {
        out.writeBoolean(value != null);
        if (value != null) {
            out.writeUTF(value);
        }
    }

    static String readNullable(DataInputStream in) throws IOException {
        return in.readBoolean() ? in.readUTF() : null;
    }
}
