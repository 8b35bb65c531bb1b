package studio.server.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

class ArgsTest {

    private static int frames(String[] args) {
        return args.length == 2 && args[0].equals("--frames") ? Args.positive(args, 1, "--frames") : 15;
    }

    @Test
    void aCommandLineThatIsOneGivesItsOptionsAndWritesNothing() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();

        Integer frames = Args.options(new String[] {"--frames", "7"}, ArgsTest::frames, "usage: x [--frames N]",
                new PrintStream(err, true, StandardCharsets.UTF_8));

        assertThat(frames).isEqualTo(7);
        assertThat(err.size()).isZero();
    }

    @Test
    void aBadOneGivesNothingAndWritesTheErrorAndTheUsage() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();

        Integer frames = Args.options(new String[] {"--frames", "0"}, ArgsTest::frames, "usage: x [--frames N]",
                new PrintStream(err, true, StandardCharsets.UTF_8));

        assertThat(frames).isNull();
        assertThat(err.toString(StandardCharsets.UTF_8)).isEqualTo(
                "error: --frames needs a positive whole number, not '0'" + System.lineSeparator()
                        + "usage: x [--frames N]" + System.lineSeparator());
    }
}
