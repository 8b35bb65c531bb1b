package studio.server.system;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

import jakarta.servlet.ReadListener;
import jakarta.servlet.ServletInputStream;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletRequestWrapper;

/**
 * A request whose body has been read already ({@link BodyArrivalFilter}): the controller reads the
 * bytes that arrived, or meets the refusal that stopped them (too large, too slow, no memory) on
 * its first read, as it would have met it reading from the connection.
 */
final class ArrivedBody extends HttpServletRequestWrapper {

    private byte[] bytes = new byte[0];
    private int length;
    private RuntimeException refusal;

    ArrivedBody(HttpServletRequest request) {
        super(request);
    }

    /** Appends bytes as they arrive; the array grows as needed, never ahead of what came. */
    void append(byte[] buffer, int offset, int count) {
        if (length + count > bytes.length) {
            long wanted = Math.max((long) length + count, Math.max(8192, 2L * bytes.length));
            bytes = Arrays.copyOf(bytes, (int) Math.min(wanted, Integer.MAX_VALUE - 8));
        }
        System.arraycopy(buffer, offset, bytes, length, count);
        length += count;
    }

    int length() {
        return length;
    }

    /** The body stopped arriving for this reason: the reader meets it instead of the bytes. */
    void refuse(RuntimeException reason) {
        this.refusal = reason;
    }

    @Override
    public ServletInputStream getInputStream() {
        return new Replay();
    }

    @Override
    public BufferedReader getReader() {
        String encoding = getCharacterEncoding();
        Charset charset = encoding != null ? Charset.forName(encoding) : StandardCharsets.UTF_8;
        return new BufferedReader(new InputStreamReader(getInputStream(), charset));
    }

    private final class Replay extends ServletInputStream {
        private int position;

        @Override
        public int read() {
            refused();
            return position < length ? bytes[position++] & 0xff : -1;
        }

        @Override
        public int read(byte[] buffer, int offset, int count) {
            refused();
            if (count == 0) {
                return 0;
            }
            if (position >= length) {
                return -1;
            }
            int n = Math.min(count, length - position);
            System.arraycopy(bytes, position, buffer, offset, n);
            position += n;
            return n;
        }

        @Override
        public int available() {
            return refusal != null ? 0 : length - position;
        }

        private void refused() {
            if (refusal != null) {
                throw refusal;
            }
        }

        @Override
        public boolean isFinished() {
            return refusal == null && position >= length;
        }

        @Override
        public boolean isReady() {
            return true;
        }

        @Override
        public void setReadListener(ReadListener listener) {
            try {
                if (refusal != null) {
                    listener.onError(refusal);
                } else {
                    listener.onDataAvailable();
                    listener.onAllDataRead();
                }
            } catch (IOException e) {
                listener.onError(e);
            }
        }
    }
}
