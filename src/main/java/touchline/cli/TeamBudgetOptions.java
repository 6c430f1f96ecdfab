package touchline.cli;

import picocli.CommandLine.Option;
import touchline.app.TeamBudget;
import touchline.model.RuleProfile;
import touchline.model.RuleProfileException;
import touchline.model.TeamMessageBudget;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.Optional;

/** The budget guard's options, shared by the commands that listen to a team ({@code listen}, {@code console}). */
final class TeamBudgetOptions {

    @Option(names = "--team", defaultValue = "0",
            description = "our team number: count its team messages (UDP 10000 + team) against the profile's budget")
    int team;

    @Option(names = "--profile", defaultValue = RuleProfile.DEFAULT, paramLabel = "NAME|FILE",
            description = "league rules: hsl-2026 (default), spl-2025, hl-2025, lab (samples/profiles), or a .properties file")
    String profile;

    @Option(names = "--team-port", defaultValue = "0",
            description = "port the team's messages arrive on (default 10000 + team)")
    int teamPort;

    /** Starts {@code guard} when a team is given; a profile that cannot be read ends the command. */
    Optional<TeamMessageBudget> guard(TeamBudget guard, String bind) throws StartFailure {
        if (team <= 0) {
            return Optional.empty();
        }
        RuleProfile rules;
        try {
            rules = RuleProfile.named(profile);
        } catch (RuleProfileException e) {
            throw StartFailure.badInput(e.getMessage());
        }
        int port = teamPort > 0 ? teamPort : guard.defaultPort(team);
        try {
            return Optional.of(guard.guard(rules, team, new InetSocketAddress(bind, port)));
        } catch (IOException e) {
            throw StartFailure.teamPortInUse(bind, port);
        }
    }
}
