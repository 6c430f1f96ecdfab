package touchline.app;

import touchline.model.MatchDebugRule;
import touchline.model.RuleProfile;
import touchline.model.TeamMessageBudget;
import touchline.transport.TeamMessageListener;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.Optional;

/**
 * The budget guard: a team's messages heard on their own port and counted against the rule
 * profile's budget (with the GameController's own figure when one is heard), and the profile's debug
 * rule's limits for the rule measured on every robot ({@link MatchDebugRule}). Off until {@link #guard} is called.
 */
public final class TeamBudget {

    private final LiveField field;
    private TeamMessageListener listener;
    private TeamMessageBudget budget;
    private AutoCloseable budgetSubscription;

    TeamBudget(LiveField field) {
        this.field = field;
    }

    /**
     * Starts the budget guard for {@code team} under {@code profile}: listens to the team's
     * messages on {@code bind} (usually 0.0.0.0:10000+team) and counts them against the
     * profile's budget, with the GameController's own figure when one is heard. A second call
     * replaces the first.
     */
    public synchronized TeamMessageBudget guard(RuleProfile profile, int team, InetSocketAddress bind) throws IOException {
        stop();
        budget = new TeamMessageBudget(field.modelClock(), profile, team);
        budgetSubscription = field.bus().subscribe(budget);
        field.matchRule().use(MatchDebugRule.Limits.of(profile));
        listener = new TeamMessageListener(bind, field::acceptTeamMessage, field.clock()).start();
        return budget;
    }

    /** The port a team's messages go to by the rules (10000 + team). */
    public int defaultPort(int team) {
        return TeamMessageListener.portOf(team);
    }

    /** The port the team's messages are heard on, or -1 without a budget guard. */
    public synchronized int port() {
        try {
            return listener == null ? -1 : listener.localAddress().getPort();
        } catch (IOException e) {
            return -1;
        }
    }

    /** The budget guard's meter as JSON, for serving ({@code /team/budget}); its state is null without a guard. */
    public TeamBudgetJson json() {
        return new TeamBudgetJson(this::budget);
    }

    /** The budget guard, if started. */
    public synchronized Optional<TeamMessageBudget> budget() {
        return Optional.ofNullable(budget);
    }

    public synchronized void stop() {
        if (listener != null) {
            listener.close();
            listener = null;
        }
        try {
            if (budgetSubscription != null) {
                budgetSubscription.close();
            }
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
        budgetSubscription = null;
        budget = null;
    }
}
