package studio.server.cluster;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.util.LinkedHashMap;
import java.util.Map;

import studio.server.job.JobEvent;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.job.TileEvent;

/** The codecs of the cluster's records: each field in order, a tag before each kind of event. */
final class ClusterCodecs {

    private static final byte STATUS = 1, TILE = 2;
    private static final JobState[] STATES = JobState.values();
    /** More workers than any cluster has: a longer map is not a status a member wrote. */
    private static final int MAX_WORKERS = 4_096;

    private ClusterCodecs() {
    }

    static final Codec<JobStatus> JOB_STATUS = new Codec<>() {
        @Override
        public void write(DataOutputStream out, JobStatus s) throws IOException {
            out.writeUTF(s.id());
            out.writeByte(s.state().ordinal());
            out.writeDouble(s.progress());
            out.writeLong(s.elapsedMillis());
            out.writeBoolean(s.raysPerSecond() != null);
            if (s.raysPerSecond() != null) {
                out.writeDouble(s.raysPerSecond());
            }
            out.writeInt(s.width());
            out.writeInt(s.height());
            Codec.writeNullable(out, s.fileName());
            Codec.writeNullable(out, s.mediaType());
            Codec.writeNullable(out, s.error());
            out.writeInt(s.workers() == null ? -1 : s.workers().size());
            if (s.workers() != null) {
                for (Map.Entry<String, Integer> worker : s.workers().entrySet()) {
                    out.writeUTF(worker.getKey());
                    out.writeInt(worker.getValue());
                }
            }
        }

        @Override
        public JobStatus read(DataInputStream in) throws IOException {
            String id = in.readUTF();
            int state = in.readByte();
            if (state < 0 || state >= STATES.length) {
                throw new IOException("no such state: " + state);
            }
            double progress = in.readDouble();
            long elapsed = in.readLong();
            Double rays = in.readBoolean() ? in.readDouble() : null;
            int width = in.readInt(), height = in.readInt();
            String fileName = Codec.readNullable(in), mediaType = Codec.readNullable(in), error = Codec.readNullable(in);
            int workers = in.readInt();
            if (workers > MAX_WORKERS) {
                throw new IOException("too many workers: " + workers);
            }
            Map<String, Integer> count = null;
            if (workers >= 0) {
                count = new LinkedHashMap<>();
                for (int i = 0; i < workers; i++) {
                    count.put(in.readUTF(), in.readInt());
                }
            }
            return new JobStatus(id, STATES[state], progress, elapsed, rays, width, height, fileName, mediaType, error,
                    count);
        }
    };

    static final Codec<JobRecord> JOB_RECORD = new Codec<>() {
        @Override
        public void write(DataOutputStream out, JobRecord job) throws IOException {
            JOB_STATUS.write(out, job.status());
            out.writeUTF(job.owner());
            out.writeInt(job.tileSize());
            out.writeUTF(job.principal());
        }

        @Override
        public JobRecord read(DataInputStream in) throws IOException {
            return new JobRecord(JOB_STATUS.read(in), in.readUTF(), in.readInt(), in.readUTF());
        }
    };

    static final Codec<JobEvent> EVENT = new Codec<>() {
        @Override
        public void write(DataOutputStream out, JobEvent event) throws IOException {
            if (event instanceof JobStatus status) {
                out.writeByte(STATUS);
                JOB_STATUS.write(out, status);
            } else if (event instanceof TileEvent tile) {
                out.writeByte(TILE);
                out.writeInt(tile.x());
                out.writeInt(tile.y());
                out.writeInt(tile.width());
                out.writeInt(tile.height());
                byte[] png = tile.png().getBytes(java.nio.charset.StandardCharsets.US_ASCII);
                out.writeInt(png.length);
                out.write(png);
                out.writeDouble(tile.progress());
            }
        }

        @Override
        public JobEvent read(DataInputStream in) throws IOException {
            byte kind = in.readByte();
            if (kind == STATUS) {
                return JOB_STATUS.read(in);
            }
            if (kind != TILE) {
                throw new IOException("no such event: " + kind);
            }
            int x = in.readInt(), y = in.readInt(), width = in.readInt(), height = in.readInt();
            int length = in.readInt();
            if (length < 0 || length > in.available()) {
                throw new IOException("bad tile image length: " + length);
            }
            String png = new String(in.readNBytes(length), java.nio.charset.StandardCharsets.US_ASCII);
            return new TileEvent(x, y, width, height, png, in.readDouble());
        }
    };

    static final Codec<TileTask> TILE_TASK = new Codec<>() {
        @Override
        public void write(DataOutputStream out, TileTask task) throws IOException {
            out.writeUTF(task.jobId());
            out.writeInt(task.index());
            out.writeInt(task.attempt());
        }

        @Override
        public TileTask read(DataInputStream in) throws IOException {
            return new TileTask(in.readUTF(), in.readInt(), in.readInt());
        }
    };

    static final Codec<TileClaim> TILE_CLAIM = new Codec<>() {
        @Override
        public void write(DataOutputStream out, TileClaim claim) throws IOException {
            out.writeUTF(claim.member());
            out.writeInt(claim.attempt());
        }

        @Override
        public TileClaim read(DataInputStream in) throws IOException {
            return new TileClaim(in.readUTF(), in.readInt());
        }
    };

    static final Codec<TileResult> TILE_RESULT = new Codec<>() {
        @Override
        public void write(DataOutputStream out, TileResult result) throws IOException {
            out.writeInt(result.index());
            out.writeInt(result.attempt());
            out.writeLong(result.rays());
            out.writeLong(result.samples());
            out.writeLong(result.nonFinite());
            out.writeUTF(result.worker());
            Codec.writeNullable(out, result.error());
            double[] rgb = result.rgb();
            out.writeInt(rgb == null ? -1 : rgb.length);
            if (rgb != null) { // in one piece: a tile is some 100 KB of doubles
                ByteBuffer bytes = ByteBuffer.allocate(rgb.length * Double.BYTES);
                bytes.asDoubleBuffer().put(rgb);
                out.write(bytes.array());
            }
        }

        @Override
        public TileResult read(DataInputStream in) throws IOException {
            int index = in.readInt(), attempt = in.readInt();
            long rays = in.readLong(), samples = in.readLong(), nonFinite = in.readLong();
            String worker = in.readUTF(), error = Codec.readNullable(in);
            int length = in.readInt();
            if (length > in.available() / Double.BYTES) {
                throw new IOException("bad pixel count: " + length);
            }
            double[] rgb = null;
            if (length >= 0) {
                rgb = new double[length];
                ByteBuffer.wrap(in.readNBytes(length * Double.BYTES)).asDoubleBuffer().get(rgb);
            }
            return new TileResult(index, attempt, rgb, rays, samples, nonFinite, worker, error);
        }
    };
}
