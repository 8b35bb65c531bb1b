package studio.server.system;

import java.io.IOException;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.springframework.util.unit.DataSize;
import org.springframework.web.filter.OncePerRequestFilter;

import jakarta.servlet.AsyncContext;
import jakarta.servlet.AsyncEvent;
import jakarta.servlet.AsyncListener;
import jakarta.servlet.FilterChain;
import jakarta.servlet.ReadListener;
import jakarta.servlet.ServletException;
import jakarta.servlet.ServletInputStream;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * Reads every request body before the request reaches its controller, without holding a request
 * thread while the body is on its way. What has arrived already is read at once; if that is the
 * whole body (a small scene comes in the same packets as its headers) the request goes on as it
 * is. Otherwise the request is put aside (servlet async I/O): the rest is read as it arrives,
 * on the container's threads, a chunk at a time, and once it is all here the request is handed
 * back to the container to run. A client that declares a large body and sends it slowly, or not
 * at all, so holds a connection and what it sent ({@link IntakeMemory}), never a thread.
 *
 * <p>A body may take {@code grace}, and then as long again as its bytes need at {@code minRate}
 * a second (the defaults: 10 s and 256 KiB/s, so a 32 MiB body may take 2 min 18 s); one that
 * falls behind gets 408, whether it trickles or stops. Bodies refused while arriving (too large,
 * no memory, too slow) reach the controller as that refusal, which its first read throws, so the
 * answers are the API's usual problems.
 */
final class BodyArrivalFilter extends OncePerRequestFilter {

    /** Set on a request whose body is arriving in the background. */
    static final String ARRIVING = BodyArrivalFilter.class.getName() + ".arriving";
    private static final int CHUNK = 16 * 1024;

    private final long graceNanos;
    private final long minBytesPerSecond;
    private final long maxBodyBytes;
    /** When a body arriving in the background falls behind its deadline: one thread for all. */
    private final ScheduledExecutorService clock;

    BodyArrivalFilter(Duration grace, DataSize minRate, long maxBodyBytes) {
        if (grace.isNegative() || minRate.toBytes() <= 0) {
            throw new IllegalArgumentException("a body's grace must not be negative and its minimum rate must be "
                    + "positive: " + grace + ", " + minRate);
        }
        this.graceNanos = grace.toNanos();
        this.minBytesPerSecond = minRate.toBytes();
        this.maxBodyBytes = maxBodyBytes;
        ScheduledThreadPoolExecutor clock = new ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, "body-clock");
            t.setDaemon(true);
            return t;
        });
        clock.setRemoveOnCancelPolicy(true);
        this.clock = clock;
    }

    @Override
    public void destroy() {
        clock.shutdownNow();
    }

    @Override
    protected boolean shouldNotFilter(HttpServletRequest request) {
        long declared = request.getContentLengthLong();
        return declared == 0 || declared < 0 && request.getHeader("Transfer-Encoding") == null;
    }

    @Override
    protected void doFilterInternal(HttpServletRequest request, HttpServletResponse response, FilterChain chain)
            throws ServletException, IOException {
        Arrival arrival = new Arrival(request);
        ServletInputStream in = request.getInputStream();
        try {
            if (arrival.readWhatHasArrived(in)) {
                chain.doFilter(arrival.body, response);
                return;
            }
        } catch (RuntimeException refused) {
            arrival.body.refuse(refused);
            chain.doFilter(arrival.body, response);
            return;
        }
        if (!request.isAsyncSupported()) {
            chain.doFilter(request, response); // read on this thread, as the body comes
            return;
        }
        request.setAttribute(ARRIVING, Boolean.TRUE);
        ContinueInvitation.sendIfExpected(request);
        arrival.readInBackground(request.startAsync(arrival.body, response), in);
    }

    /** One request's body on its way. */
    private final class Arrival implements ReadListener, AsyncListener {
        final ArrivedBody body;
        private final long declared;
        private final long start = System.nanoTime();
        private final byte[] chunk = new byte[CHUNK];
        private final AtomicBoolean handedOn = new AtomicBoolean();
        private volatile long received;
        private AsyncContext async;
        private ServletInputStream in;

        Arrival(HttpServletRequest request) {
            this.body = new ArrivedBody(request);
            this.declared = request.getContentLengthLong();
        }

        /** Reads what can be read without waiting; true if that was the whole body. */
        boolean readWhatHasArrived(ServletInputStream stream) throws IOException {
            while (received != declared && stream.available() > 0) {
                int n = stream.read(chunk, 0, chunk.length);
                if (n < 0) {
                    return true;
                }
                arrived(n);
            }
            return received == declared || declared < 0 && stream.isFinished();
        }

        private void arrived(int n) {
            body.append(chunk, 0, n);
            received += n;
            long elapsed = System.nanoTime() - start;
            if (elapsed > graceNanos && (double) (elapsed - graceNanos) / 1e9 * minBytesPerSecond > received) {
                throw tooSlow(elapsed);
            }
        }

        void readInBackground(AsyncContext context, ServletInputStream stream) {
            this.async = context;
            this.in = stream;
            // the container's own bound, past any body the rate allows; the clock below acts first
            async.setTimeout(TimeUnit.NANOSECONDS.toMillis(graceNanos) + maxBodyBytes * 1000 / minBytesPerSecond
                    + 10_000);
            async.addListener(this);
            checkLater();
            in.setReadListener(this);
        }

        @Override
        public void onDataAvailable() throws IOException {
            try {
                while (!handedOn.get() && in.isReady()) {
                    int n = in.read(chunk, 0, chunk.length);
                    if (n < 0) {
                        break;
                    }
                    arrived(n);
                }
            } catch (RuntimeException refused) {
                handOn(refused);
            }
        }

        @Override
        public void onAllDataRead() {
            handOn(null);
        }

        @Override
        public void onError(Throwable failure) {
            // the connection failed (the client went away): nobody is left to answer
            if (handedOn.compareAndSet(false, true)) {
                async.complete();
            }
        }

        /** The body falls behind at the moment its bytes so far stop sufficing; looks again then. */
        private void checkLater() {
            if (handedOn.get()) {
                return;
            }
            long due = start + graceNanos + (long) (received * 1e9 / minBytesPerSecond);
            long wait = due - System.nanoTime();
            if (wait <= 0) {
                handOn(tooSlow(System.nanoTime() - start));
            } else {
                clock.schedule(this::checkLater, wait + 1_000_000, TimeUnit.NANOSECONDS);
            }
        }

        private RuntimeException tooSlow(long elapsedNanos) {
            return new BodyTimeoutException(String.format(Locale.ROOT, "the request body came too slowly: %d bytes "
                    + "in %.1f s; after %d s a body must keep coming at %d KiB/s on average "
                    + "(studio.limits.body-grace, studio.limits.min-body-rate)", received, elapsedNanos / 1e9,
                    Duration.ofNanos(graceNanos).toSeconds(), minBytesPerSecond >> 10));
        }

        /** The body is here, or refused: the request runs now, on a container thread. */
        private void handOn(RuntimeException refusal) {
            if (handedOn.compareAndSet(false, true)) {
                if (refusal != null) {
                    body.refuse(refusal);
                }
                async.dispatch();
            }
        }

        @Override
        public void onTimeout(AsyncEvent event) {
            handOn(tooSlow(System.nanoTime() - start));
        }

        @Override
        public void onComplete(AsyncEvent event) {
        }

        @Override
        public void onError(AsyncEvent event) {
        }

        @Override
        public void onStartAsync(AsyncEvent event) {
        }
    }
}
