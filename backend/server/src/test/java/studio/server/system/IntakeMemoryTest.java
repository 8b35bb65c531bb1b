package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;
import org.springframework.mock.web.MockFilterChain;
import org.springframework.mock.web.MockHttpServletRequest;
import org.springframework.mock.web.MockHttpServletResponse;

/** A request's memory: reserved as its body arrives, grown by its compile, handed over to its render. */
class IntakeMemoryTest {

    @Test
    void aBodyReservesWhatHasArrivedNotWhatItDeclares() throws Exception {
        MemoryBudget budget = new MemoryBudget(1L << 30);
        IntakeMemoryFilter filter = new IntakeMemoryFilter(budget);
        MockHttpServletRequest request = new MockHttpServletRequest("POST", "/api/render");
        request.setContent(new byte[1 << 20]); // declares a MiB
        long[] held = new long[2];

        filter.doFilter(request, new MockHttpServletResponse(), (req, res) -> {
            held[0] = budget.reserved();
            req.getInputStream().readNBytes(10);
            held[1] = budget.reserved();
        });

        assertThat(held[0]).as("before a byte is read").isZero();
        assertThat(held[1]).as("after ten").isEqualTo(10 * BodyMemory.BYTES_PER_BYTE);
        assertThat(budget.reserved()).as("when the request has been handled").isZero();
    }

    @Test
    void whatABodyBuildsWhenParsedIsReckonedAsItArrives() {
        byte[] text = "\"v 0 0 0\\nf 1 1 1\"".getBytes(StandardCharsets.UTF_8);
        byte[] structure = "{\"a\":[1,2]}".getBytes(StandardCharsets.UTF_8);

        assertThat(BodyMemory.of(text, 0, text.length)).isEqualTo(BodyMemory.BYTES_PER_BYTE * text.length);
        assertThat(BodyMemory.of(structure, 0, structure.length)).isEqualTo(BodyMemory.BYTES_PER_BYTE * 11
                + BodyMemory.PER_OBJECT + BodyMemory.PER_MEMBER + BodyMemory.PER_ARRAY + BodyMemory.PER_ELEMENT);
        assertThat(BodyMemory.of(structure, 1, 3)).as("a slice").isEqualTo(BodyMemory.BYTES_PER_BYTE * 3);
    }

    @Test
    void aBodyLargerThanTheWholeBudgetGets413AsItArrives() throws Exception {
        MemoryBudget budget = new MemoryBudget(1000);
        MockHttpServletRequest request = new MockHttpServletRequest("POST", "/api/render");
        request.setContent(new byte[200]); // 200 x 8 = 1600 > 1000

        MemoryExceededException e = catchThrowableOfType(MemoryExceededException.class,
                () -> new IntakeMemoryFilter(budget).doFilter(request, new MockHttpServletResponse(),
                        (req, res) -> req.getInputStream().readAllBytes()));

        assertThat(e.getStatusCode().value()).isEqualTo(413);
        assertThat(e.getBody().getDetail()).contains("studio.render-memory");
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void aBodyOtherWorkLeavesNoRoomForGets503WithRetryAfter() throws Exception {
        MemoryBudget budget = new MemoryBudget(1000);
        MemoryBudget.Reservation other = budget.tryReserve(900);
        MockHttpServletRequest request = new MockHttpServletRequest("POST", "/api/jobs");
        request.setContent(new byte[100]);

        MemoryBusyException e = catchThrowableOfType(MemoryBusyException.class,
                () -> new IntakeMemoryFilter(budget).doFilter(request, new MockHttpServletResponse(),
                        (req, res) -> req.getInputStream().readAllBytes()));

        assertThat(e.getStatusCode().value()).isEqualTo(503);
        assertThat(e.getHeaders().getFirst("Retry-After")).isEqualTo("2");
        assertThat(budget.reserved()).isEqualTo(900);
        other.close();
    }

    @Test
    void memoryAWorkCanDoWithoutIsGrantedOnlyWhenFreeWithoutWaitingOrRefusing() {
        MemoryBudget budget = new MemoryBudget(1000);
        MemoryBudget.Reservation other = budget.tryReserve(900);
        IntakeMemory intake = IntakeMemory.of(budget);
        long started = System.nanoTime();

        assertThat(intake.tryReserve(200)).isFalse();
        assertThat((System.nanoTime() - started) / 1e9).as("seconds waited").isLessThan(IntakeMemory.WAIT.toSeconds() / 2.0);
        assertThat(budget.reserved()).isEqualTo(900);
        assertThat(intake.tryReserve(60)).isTrue();
        assertThat(budget.reserved()).isEqualTo(960);
        intake.close();
        other.close();
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void theCompilesShareGoesToTheRenderInOneStepAndTheBodysStaysTillTheEnd() {
        MemoryBudget budget = new MemoryBudget(1000);
        IntakeMemory intake = IntakeMemory.of(budget);
        intake.bodyArrived(new byte[10], 0, 10); // 80
        intake.reserve(600); // the engine's meshes

        // 680 held, 320 free: a render of 500 fits only because the compile gives its share back
        MemoryBudget.Reservation render = intake.handOver(budget, 500);

        assertThat(render).isNotNull();
        assertThat(intake.bytes()).as("the body's bytes").isEqualTo(10);
        assertThat(budget.reserved()).isEqualTo(510);
        intake.close();
        render.close();
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void aRequestsMemoryIsCountedWhenTheBudgetIsOverdrawnOrAnotherWaits() {
        MemoryBudget budget = new MemoryBudget(1000);
        MemoryBudget.Reservation images = budget.forceReserve(1200); // finished jobs' images beyond the budget

        IntakeMemory intake = IntakeMemory.of(budget);

        MemoryBusyException e = catchThrowableOfType(MemoryBusyException.class, () -> intake.reserve(1));
        assertThat(e).as("refused, not let through uncounted").isNotNull();
        images.close();
        intake.reserve(600);
        assertThat(budget.reserved()).isEqualTo(600);
        intake.close();
    }

    @Test
    void getRequestsPassWithoutAReservation() throws Exception {
        MemoryBudget budget = new MemoryBudget(1);
        MockHttpServletRequest request = new MockHttpServletRequest("GET", "/api/scenes");
        MockHttpServletResponse response = new MockHttpServletResponse();
        new IntakeMemoryFilter(budget).doFilter(request, response, new MockFilterChain());
        assertThat(response.getStatus()).isEqualTo(200);
        assertThat(IntakeMemory.of(request)).isSameAs(IntakeMemory.NONE);
    }
}
