package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.springframework.mock.web.MockFilterChain;
import org.springframework.mock.web.MockHttpServletRequest;
import org.springframework.mock.web.MockHttpServletResponse;

class MemoryBudgetTest {

    @Test
    void reservesWhatIsFreeAndRefusesTheRest() {
        MemoryBudget budget = new MemoryBudget(100);
        MemoryBudget.Reservation sixty = budget.tryReserve(60);
        assertThat(sixty).isNotNull();
        assertThat(budget.tryReserve(41)).isNull();
        MemoryBudget.Reservation forty = budget.tryReserve(40);
        assertThat(forty).isNotNull();
        assertThat(budget.reserved()).isEqualTo(100);
        sixty.close();
        sixty.close(); // twice gives back once
        assertThat(budget.reserved()).isEqualTo(40);
        forty.close();
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void forcedReservationMayGoBeyondTheBudgetAndBlocksNewWork() {
        MemoryBudget budget = new MemoryBudget(100);
        MemoryBudget.Reservation image = budget.forceReserve(150);
        assertThat(budget.tryReserve(1)).isNull();
        image.close();
        assertThat(budget.tryReserve(100)).isNotNull();
    }

    @Test
    void refusesNonsense() {
        assertThatThrownBy(() -> new MemoryBudget(0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new MemoryBudget(10).tryReserve(-1)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> MemoryBudget.ofHeapShare(1.5)).isInstanceOf(IllegalArgumentException.class);
        assertThat(MemoryBudget.ofHeapShare(0.5).capacity()).isEqualTo(Runtime.getRuntime().maxMemory() / 2);
    }

    @Test
    void bodyTheBudgetCannotCoverGets503WithRetryAfterAndIsNeverRead() throws Exception {
        MemoryBudget budget = new MemoryBudget(1000);
        IntakeMemoryFilter filter = new IntakeMemoryFilter(budget, 10_000);
        MockHttpServletRequest request = new MockHttpServletRequest("POST", "/api/render");
        request.setContent(new byte[200]); // 200 x 8 = 1600 > 1000
        MockHttpServletResponse response = new MockHttpServletResponse();
        MockFilterChain chain = new MockFilterChain();
        filter.doFilter(request, response, chain);
        assertThat(response.getStatus()).isEqualTo(503);
        assertThat(response.getHeader("Retry-After")).isEqualTo("2");
        assertThat(response.getContentType()).isEqualTo("application/problem+json");
        assertThat(chain.getRequest()).as("the request went no further").isNull();
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void bodyWithinTheBudgetHoldsItsShareWhileHandledThenGivesItBack() throws Exception {
        MemoryBudget budget = new MemoryBudget(1000);
        IntakeMemoryFilter filter = new IntakeMemoryFilter(budget, 10_000);
        MockHttpServletRequest request = new MockHttpServletRequest("POST", "/api/render");
        request.setContent(new byte[100]);
        long[] seen = new long[1];
        filter.doFilter(request, new MockHttpServletResponse(), (req, res) -> seen[0] = budget.reserved());
        assertThat(seen[0]).isEqualTo(100 * IntakeMemoryFilter.INTAKE_FACTOR);
        assertThat(budget.reserved()).isZero();
    }

    @Test
    void bodyOfUnknownLengthCountsAtTheBodyLimit() throws Exception {
        MemoryBudget budget = new MemoryBudget(1000);
        IntakeMemoryFilter filter = new IntakeMemoryFilter(budget, 200); // 200 x 8 > 1000
        MockHttpServletRequest chunked = new MockHttpServletRequest("POST", "/api/jobs") {
            @Override
            public long getContentLengthLong() {
                return -1;
            }
        };
        MockHttpServletResponse response = new MockHttpServletResponse();
        filter.doFilter(chunked, response, new MockFilterChain());
        assertThat(response.getStatus()).isEqualTo(503);
    }

    @Test
    void getRequestsPassWithoutAReservation() throws Exception {
        MemoryBudget budget = new MemoryBudget(1);
        IntakeMemoryFilter filter = new IntakeMemoryFilter(budget, 10_000);
        MockHttpServletResponse response = new MockHttpServletResponse();
        filter.doFilter(new MockHttpServletRequest("GET", "/api/scenes"), response, new MockFilterChain());
        assertThat(response.getStatus()).isEqualTo(200);
    }
}
