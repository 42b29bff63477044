// The planners `foldkit plan --planner` takes, as `GET /api` lists them (the planners' own table,
// planners::planner_names()): the page offers what the CLI plans with, and a planner added there
// is offered here without an edit.

/** The planner list's choices for GET /api's answer `server`, in the server's order:
 * [{name, selected, refused}], foldkit's default planner selected, `refused` saying why foldkit
 * cannot plan with one ('' when it can). Empty when the answer lists none (it did not come). */
export function plannerChoices(server) {
  const planners = server && Array.isArray(server.planners) ? server.planners : [];
  return planners.map((p) => ({ name: String(p.name), selected: p.default === true, refused: p.refused ? String(p.refused) : '' }));
}

/** Fills the `<select>` with the planners of `server` (GET /api's answer); a planner foldkit
 * refuses stays listed, disabled, with the reason as its tooltip. Without a list the select is
 * left as index.html has it: its one choice, by no name, plans with foldkit's own default.
 * Returns whether it was filled. */
export function fillPlanners(select, server) {
  const choices = plannerChoices(server);
  if (!choices.length) return false;
  select.replaceChildren(...choices.map((c) => {
    const option = new Option(c.name, c.name, c.selected, c.selected);
    if (c.refused) {
      option.disabled = true;
      option.title = c.refused;
    }
    return option;
  }));
  return true;
}
