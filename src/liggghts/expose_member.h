// Access to a member LIGGGHTS keeps private, by explicit instantiation (why this way and not
// another: liggghts_members.cpp). Per member: a tag, HARDCONTACT_MEMBER_TAG(Tag, <member
// pointer type>) (a struct with `using type = ...;` and `friend type member(Tag);`), then,
// once in the program, `template struct ExposeMember<Tag, &Class::member_>;`;
// `obj->*member(Tag{})` reaches it.
#pragma once

// a struct per tag, not a template: a friend declared in a class template is a non-template
// function g++ warns about (-Wnon-template-friend)
#define HARDCONTACT_MEMBER_TAG(Tag, ...) \
  struct Tag {                           \
    using type = __VA_ARGS__;            \
    friend type member(Tag);             \
  };

namespace hardcontact {
namespace liggghts {
// unnamed, as the tags of each file that uses it: the friend it defines must live in the tags'
// namespace
namespace {

template <typename Tag, typename Tag::type Member>
struct ExposeMember {
  friend typename Tag::type member(Tag) { return Member; }
};

}    // namespace
}    // namespace liggghts
}    // namespace hardcontact
