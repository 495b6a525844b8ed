/* accelab's search ranking: prose before API objects.
 *
 * Sphinx's default ranks a match on an object's name (an API function called
 * "grade") far above a page whose title and text are about the word (the
 * instructor's guide to grading). A reader who types a word wants the page
 * that explains it; one who types a dotted or underscored name wants the API.
 * So object results lose their bonus unless the query looks like an
 * identifier, and the guide and the course (the pages written for readers)
 * come before the API reference at equal relevance.
 */
var Scorer = {
  score: function (result) {
    var docname = result[0], score = result[4], kind = result[6];
    var query = new URLSearchParams(window.location.search).get("q") || "";
    var identifier = /[._]/.test(query);
    if (kind === "object" && !identifier) score -= 20;
    if (docname.indexOf("guide/") === 0) score += 6;
    else if (docname.indexOf("course/") === 0 || docname === "syllabus") score += 3;
    else if (docname.indexOf("api/") === 0 && !identifier) score -= 3;
    return score;
  },
  objNameMatch: 11,
  objPartialMatch: 6,
  objPrio: {0: 15, 1: 5, 2: -5},
  objPrioDefault: 0,
  title: 15,
  partialTitle: 7,
  term: 5,
  partialTerm: 2,
};
