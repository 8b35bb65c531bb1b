package studio.server.system;

import java.io.IOException;

import jakarta.servlet.ReadListener;
import jakarta.servlet.ServletInputStream;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletRequestWrapper;

/**
 * A request whose body stream shows every chunk it reads to a {@link Watcher} before the reader
 * gets it; the watcher refuses the rest of the body by throwing.
 */
final class WatchedBody extends HttpServletRequestWrapper {

    /** Sees each chunk of the body as it arrives. */
    @FunctionalInterface
    interface Watcher {
        void arrived(byte[] buffer, int offset, int length);
    }

    private final Watcher watcher;
    private ServletInputStream stream;

    WatchedBody(HttpServletRequest request, Watcher watcher) {
        super(request);
        this.watcher = watcher;
    }

    @Override
    public ServletInputStream getInputStream() throws IOException {
        if (stream == null) {
            stream = new WatchedStream(super.getInputStream(), watcher);
        }
        return stream;
    }

    private static final class WatchedStream extends ServletInputStream {
        private final ServletInputStream in;
        private final Watcher watcher;
        private final byte[] one = new byte[1];

        WatchedStream(ServletInputStream in, Watcher watcher) {
            this.in = in;
            this.watcher = watcher;
        }

        @Override
        public int read() throws IOException {
            int b = in.read();
            if (b >= 0) {
                one[0] = (byte) b;
                watcher.arrived(one, 0, 1);
            }
            return b;
        }

        @Override
        public int read(byte[] buffer, int offset, int length) throws IOException {
            int n = in.read(buffer, offset, length);
            if (n > 0) {
                watcher.arrived(buffer, offset, n);
            }
            return n;
        }

        @Override
        public int available() throws IOException {
            return in.available();
        }

        @Override
        public boolean isFinished() {
            return in.isFinished();
        }

        @Override
        public boolean isReady() {
            return in.isReady();
        }

        @Override
        public void setReadListener(ReadListener listener) {
            in.setReadListener(listener);
        }
    }
}
